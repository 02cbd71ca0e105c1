#include "garden/cli/load_model.h"

#include <fstream>
#include <iostream>
#include <sstream>

#include "frep/parser.h"

namespace hg::garden::cli {

int pickBody(const frep::Program& program, const std::string& name, const std::string& file) {
    int body = name.empty() ? program.defaultBody() : program.findBody(name);
    if (body >= 0) return body;
    std::cerr << file << ": error: no body named '" << name << "'; the file defines:";
    for (const auto& b : program.bodies) std::cerr << " " << b.spelling;
    std::cerr << "\n";
    return -1;
}

std::optional<LoadedModel> loadModel(const ModelOptions& options) {
    frep::ParseResult parsed = frep::parseFile(options.file);
    for (const auto& d : parsed.errors) std::cerr << frep::formatDiagnostic(d);
    if (!parsed.ok()) return std::nullopt;
    LoadedModel lm;
    lm.program = std::make_shared<const frep::Program>(std::move(*parsed.program));
    int body = pickBody(*lm.program, options.body, options.file);
    if (body < 0) return std::nullopt;
    lm.model.emplace(lm.program, body, options.parameters);
    return lm;
}

}  // namespace hg::garden::cli
