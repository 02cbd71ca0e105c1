#include "garden/cli/load_model.h"

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>

#include "frep/parser.h"
#include "voxel/vdb_io.h"

namespace hg::garden::cli {

bool parseNumberList(const std::string& text, std::vector<double>& out) {
    out.clear();
    if (text.empty()) return true;
    std::stringstream s(text);
    std::string item;
    while (std::getline(s, item, ',')) {
        char* end = nullptr;
        double v = std::strtod(item.c_str(), &end);
        if (item.empty() || end == item.c_str() || *end != '\0') return false;
        out.push_back(v);
    }
    return true;
}

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

bool boxOption(const std::vector<double>& numbers, std::optional<frep::Box3>& box) {
    box.reset();
    if (numbers.empty()) return true;
    if (numbers.size() != 6) {
        std::cerr << "error: --box expects six numbers: x0,y0,z0,x1,y1,z1\n";
        return false;
    }
    frep::Box3 b;
    for (int a = 0; a < 3; ++a) {
        b.lo[a] = numbers[static_cast<size_t>(a)];
        b.hi[a] = numbers[static_cast<size_t>(a + 3)];
    }
    box = b;
    return true;
}

bool outputWritable(const std::string& path) {
    std::string why = voxel::checkWritable(path);
    if (!why.empty()) std::cerr << "error: " << why << "\n";
    return why.empty();
}

}  // namespace hg::garden::cli
