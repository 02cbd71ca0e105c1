// `hypergarden check FILE.hf [--body NAME] [--a V,...]`: parses the file,
// lists its bodies and parameters, says which evaluation path the chosen body
// takes, and estimates the model box by interval subdivision.
#include <cstdio>
#include <iostream>

#include "frep/eval/bounds.h"
#include "frep/language/parser.h"
#include "cli/commands.h"
#include "cli/load_model.h"

namespace hg::garden::cli {

int runCheck(const ModelOptions& options) {
    frep::ParseResult parsed = frep::parseFile(options.file);
    for (const auto& d : parsed.errors) std::cerr << frep::formatDiagnostic(d);
    if (!parsed.ok()) {
        std::cerr << options.file << ": " << parsed.errors.size() << " error"
                  << (parsed.errors.size() == 1 ? "" : "s") << "\n";
        return 1;
    }
    auto program = std::make_shared<const frep::Program>(std::move(*parsed.program));
    std::cout << options.file << ": " << program->bodies.size() << " bod"
              << (program->bodies.size() == 1 ? "y" : "ies") << "\n";
    for (const auto& b : program->bodies) {
        std::cout << "  " << b.spelling << "(x[" << b.xSize() << "], a[" << b.aSize() << "]";
        if (b.declaresS) std::cout << ", s[" << b.sSize() << "]";
        std::cout << ")  line " << b.loc.line << ", " << b.variables.size() << " variables, "
                  << b.arrays.size() - 3 << " local arrays\n";
    }
    int body = pickBody(*program, options.body, options.file);
    if (body < 0) return 1;
    frep::Model model(program, body, options.parameters);
    const auto& b = model.body();
    std::cout << "body: " << b.spelling << "\n";
    std::cout << "parameters: a[1.." << b.aSize() << "] =";
    for (int i = 0; i < b.aSize(); ++i)
        std::cout << " " << (static_cast<size_t>(i) < options.parameters.size() ? options.parameters[static_cast<size_t>(i)] : 0.0);
    std::cout << "\n";
    std::cout << "path: " << model.pathDescription() << "\n";
    if (const frep::Tape* tape = model.tape()) {
        frep::BoundsEstimate est = frep::estimateBounds(*tape);
        if (est.empty) {
            std::cout << "model box: empty (no point of [-1024, 1024]^3 is inside)\n";
        } else {
            std::printf("model box: [%.4g, %.4g] x [%.4g, %.4g] x [%.4g, %.4g]%s (cell %.3g after %d levels)\n",
                        est.box.lo[0], est.box.hi[0], est.box.lo[1], est.box.hi[1], est.box.lo[2], est.box.hi[2],
                        !est.unbounded ? "" : est.budgetSpent ? " not separated from far space within the budget (unbounded, or loose bounds)" : " unbounded: reaches the search cube", est.cellSize, est.levels);
            std::fflush(stdout);
        }
    } else {
        std::cout << "model box: not estimated (intervals need the tape path)\n";
    }
    std::cout << "errors: 0\n";
    return 0;
}

}  // namespace hg::garden::cli
