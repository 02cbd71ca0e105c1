#include "cli/load_model.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>

#include "garden/scene/model_file.h"

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

bool parseImageSize(const std::string& text, int& width, int& height) {
    char x = 0, extra = 0;
    return std::sscanf(text.c_str(), "%d%c%d%c", &width, &x, &height, &extra) == 3 && x == 'x' &&
           width >= kMinImageSide && height >= kMinImageSide && width <= kMaxImageSide && height <= kMaxImageSide;
}

int pickBody(const frep::Program& program, const std::string& name, const std::string& file) {
    std::string why;
    int body = findBodyOrExplain(program, name, file, why);
    std::cerr << why;
    return body;
}

std::optional<LoadedModel> loadModel(const ModelOptions& options) {
    ModelFile file = loadModelFile(options.file, options.body, options.parameters);
    std::cerr << file.error;
    if (!file.ok()) return std::nullopt;
    LoadedModel lm;
    lm.program = std::move(file.program);
    lm.model = std::move(file.model);
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

}  // namespace hg::garden::cli
