// `hypergarden eval FILE.hf [--body NAME] [--a V,...] [x y z]`: the body's
// value at one point, or at each "x y z" line of standard input. A point
// where the program fails prints "error: <reason> at line L, column C".
#include <cstdio>
#include <iostream>
#include <sstream>
#include <string>

#include "frep/eval_batch.h"
#include "frep/interpreter.h"
#include "garden/cli/commands.h"
#include "garden/cli/load_model.h"

namespace hg::garden::cli {
namespace {

void printResult(const frep::PointResult& r) {
    if (r.ok()) std::printf("%.17g\n", r.value);
    else std::printf("error: %s at line %d, column %d\n", frep::describe(r.error), r.loc.line, r.loc.column);
}

frep::PointResult evalPoint(const frep::Model& model, frep::Interpreter& interp, bool forceInterpreter,
                            double x, double y, double z) {
    if (forceInterpreter || !model.tape()) return interp.evaluate(x, y, z);
    frep::BatchEvaluator<double> ev(*model.tape());
    frep::ErrorReport errors;
    std::uint8_t failed = 0;
    frep::PointResult r;
    ev.evaluate(&x, &y, &z, &r.value, 1, errors, &failed);
    if (failed) { r.error = errors.first; r.loc = errors.firstLoc; }
    return r;
}

}  // namespace

int runEval(const EvalOptions& options) {
    auto lm = loadModel(options.model);
    if (!lm) return 1;
    const frep::Model& model = *lm->model;
    frep::Interpreter interp(model.program(), model.bodyIndex(), model.parameters());
    if (!options.point.empty()) {
        if (options.point.size() != 3) {
            std::cerr << "eval: give a point as three numbers: x y z\n";
            return 2;
        }
        printResult(evalPoint(model, interp, options.interpreter, options.point[0], options.point[1], options.point[2]));
        return 0;
    }
    std::string line;
    int lineNo = 0, bad = 0;
    while (std::getline(std::cin, line)) {
        ++lineNo;
        if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
        std::istringstream s(line);
        double x, y, z;
        if (!(s >> x >> y >> z)) {
            std::cerr << "<stdin>:" << lineNo << ": error: expected three numbers \"x y z\", got \"" << line << "\"\n";
            ++bad;
            continue;
        }
        printResult(evalPoint(model, interp, options.interpreter, x, y, z));
    }
    return bad ? 1 : 0;
}

}  // namespace hg::garden::cli
