// A compiled body: a flat list of register instructions in evaluation order
// (SSA before register allocation). Leaves are the point coordinates and
// constants; a[] values are folded in at compile time. Every evaluator
// (batch float/double, interval, gradient) runs the same tape.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "frep/language/ast.h"
#include "frep/language/domain_error.h"

namespace hg::frep {

enum class Op : std::uint8_t {
    // leaves
    X, Y, Z, Const,
    // plain IEEE arithmetic (library routines, folded language ops)
    Add, Sub, Mul, Div, Neg, Abs, Sqrt, Exp, Log, Sin, Cos, Tan, Atan, Asin, Acos,
    Atan2, Pow, Floor, Ceil, Trunc, Sinh, Cosh, Tanh,
    // 0/1 results
    Lt, Le, Gt, Ge, EqEps, NeEps, And, Or, Not, Truthy,
    Select,  // a != 0 ? b : c
    Min, Max,
    // R-functions, alpha 0
    Union, Intersect, Subtract,
    // language operations that can fail (domain errors) where their guard holds
    HfDiv, HfPow, HfSqrt, HfLog, HfLog10, HfAsin, HfAcos, HfTan, HfMod,
    Check,   // fails with `error` where a == 0 (unassigned value, bad index)
    // fused library kernels; parameters in Tape::params[param...]
    ConvSegment,  // Cauchy line-segment field at (a, b, c): b, e (3 each), s
    ConvArc,      // one hfConvArc piece at (a, b, c): frame, r, s, span, over
    SoftStep,     // hfSoft's sum a plus the soft kernel at squared distance b (= c): d
    // An input given beside the point: the base value an edit expression
    // works on (garden/sculpt: a sculpture's unedited field). Only the batch
    // evaluator reads it (BatchEvaluator::evaluate with w); language
    // programs never contain it.
    W,
};

// Parameters of a ConvSegment: begin (3), end (3), kernel width.
constexpr std::uint32_t kConvSegmentParams = 7;
// Parameters of a ConvArc: centre (3), rotation into the arc's plane (3x3,
// row major), radius, kernel width, span in radians, 1 for the part beyond
// 180 degrees (turned by -180 degrees) else 0.
constexpr std::uint32_t kConvArcParams = 16;
// Parameters of a SoftStep: the radius of influence.
constexpr std::uint32_t kSoftStepParams = 1;

// Number of parameters of a fused kernel; 0 for every other opcode.
std::uint32_t fusedParamCount(Op op);

const char* opName(Op op);
int opArity(Op op);
bool opCanFail(Op op);

constexpr std::uint32_t kNoReg = 0xffffffffu;

struct Instr {
    Op op = Op::Const;
    DomainError error = DomainError::None;  // for Check
    std::uint32_t a = kNoReg, b = kNoReg, c = kNoReg;
    std::uint32_t guard = kNoReg;  // fallible ops: fail only where guard != 0
    std::uint32_t site = 0;        // index into Tape::sites, for fallible ops
    std::uint32_t param = 0;       // fused kernels: first index into Tape::params
    double imm = 0.0;              // Const value
};

struct Tape {
    // After register allocation: instruction i writes register out[i].
    std::vector<Instr> code;
    std::vector<std::uint32_t> out;
    std::uint32_t registers = 0;
    std::uint32_t result = kNoReg;  // register holding the body's value
    std::vector<SourceLoc> sites;   // locations of fallible operations
    // Where each instruction's value comes from in the source: the
    // expression or library call that built it (its first one when shared).
    // Evaluators name it when a point's value is NaN.
    std::vector<SourceLoc> locs;
    std::vector<double> params;     // constant parameters of fused kernels

    size_t size() const { return code.size(); }
    bool canFail() const;
    std::string dump() const;
};

}  // namespace hg::frep
