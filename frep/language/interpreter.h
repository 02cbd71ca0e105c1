// The scalar interpreter: evaluates a body point by point with exactly the
// reference interpreter's semantics (right-to-left operands, arrays rewritten
// in place by library routines, runtime errors). It runs every program,
// including those the tape compiler cannot flatten, and is the baseline the
// batch evaluator is checked and measured against.
#pragma once

#include <cmath>
#include <vector>

#include "frep/language/ast.h"
#include "frep/language/domain_error.h"

namespace hg::frep {

struct PointResult {
    double value = 0.0;  // the body's value, or kOutsideValue on error
    DomainError error = DomainError::None;
    SourceLoc loc;       // where the error happened
    bool ok() const { return error == DomainError::None; }
};

class Interpreter {
public:
    // `program` must outlive the interpreter. `a` fills the body's a[]
    // (missing items are 0); s[] starts at 0.
    Interpreter(const Program& program, int body, std::vector<double> a = {});

    // The reference's result: the value as computed (beyond +-kValueLimit
    // too), or the runtime error. A NaN result is an error located at the
    // first operation or library call that produced a NaN (the body's
    // assignment when none did: a NaN given in x or a[]).
    PointResult evaluate(double x, double y, double z);

    // Evaluator contract: failures and NaN become kOutsideValue and are
    // counted in `errors`; values beyond +-kValueLimit are clamped to it.
    double evaluateSafe(double x, double y, double z, ErrorReport& errors);

    int body() const { return body_; }

private:
    struct Frame {
        std::vector<std::vector<double>> arrays;
        std::vector<std::vector<unsigned char>> arrayInit;
        std::vector<double> vars;
        std::vector<unsigned char> varInit;
    };

    bool run(int body, Frame& frame, double& result);
    bool exec(const std::vector<Stmt>& stmts, const Body& body, Frame& frame);
    bool eval(const Expr& e, const Body& body, Frame& frame, double& out);
    bool evalBuiltin(const Expr& e, const Body& body, Frame& frame, double& out);
    bool evalLibrary(const Expr& e, const Body& body, Frame& frame, double& out);
    bool evalBodyCall(const Expr& e, const Body& body, Frame& frame, double& out);
    bool index(const Expr& e, const Body& body, Frame& frame, int slot, size_t& out);
    bool fail(DomainError e, SourceLoc loc);
    // Remembers where the point's first NaN was made: an operation whose
    // result is NaN while no value it was given is (a library call: no
    // scalar argument). The tape evaluators trace a NaN to the same place.
    void noteNan(double result, SourceLoc loc, bool nanIn) {
        if (std::isnan(result) && !nanIn && !nanSeen_) {
            nanSeen_ = true;
            nanLoc_ = loc;
        }
    }
    void resetFrame(int body, Frame& frame);

    const Program& program_;
    int body_;
    std::vector<double> a_;
    std::vector<Frame> frames_;  // one per body: a body only calls earlier ones
    DomainError error_ = DomainError::None;
    SourceLoc errorLoc_;
    bool nanSeen_ = false;
    SourceLoc nanLoc_;
    long long steps_ = 0;        // loop iteration guard
};

}  // namespace hg::frep
