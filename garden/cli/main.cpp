// hypergarden: the one executable. Subcommands check and evaluate HyperFun
// files; later ones voxelize, mesh, export and replay, and no subcommand will
// open the garden.
#include <CLI/CLI.hpp>

#include <iostream>

#include "garden/cli/commands.h"

int main(int argc, char** argv) {
    using namespace hg::garden::cli;
    CLI::App app{"Hypergarden: a real-time HyperFun sculpture garden"};
    app.require_subcommand(1);

    ModelOptions checkOpts;
    auto* check = app.add_subcommand("check", "Parse a HyperFun file, list its bodies, evaluation path and model box");
    check->add_option("file", checkOpts.file, "HyperFun file (.hf)")->required();
    check->add_option("--body", checkOpts.body, "Body to check (default: my_model, else the first)");
    std::string checkA, evalA;
    check->add_option("--a", checkA, "Values of a[1], a[2], ... separated by commas");

    EvalOptions evalOpts;
    auto* eval = app.add_subcommand("eval", "Evaluate a body at a point, or at \"x y z\" lines read from stdin");
    eval->add_option("file", evalOpts.model.file, "HyperFun file (.hf)")->required();
    eval->add_option("--body", evalOpts.model.body, "Body to evaluate (default: my_model, else the first)");
    eval->add_option("--a", evalA, "Values of a[1], a[2], ... separated by commas");
    eval->add_option("point", evalOpts.point, "x y z")->expected(0, 3);
    eval->add_flag("--interpreter", evalOpts.interpreter, "Use the scalar interpreter even when the body compiles");

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e);
    }
    if (!parseNumberList(checkA, checkOpts.parameters) || !parseNumberList(evalA, evalOpts.model.parameters)) {
        std::cerr << "error: --a expects numbers separated by commas, for example --a 0.5,1\n";
        return 2;
    }
    if (*check) return runCheck(checkOpts);
    if (*eval) return runEval(evalOpts);
    return 2;
}
