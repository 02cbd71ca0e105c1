#include <string>

#include "frep/language/ast.h"

namespace hg::frep {

namespace {
std::string lower(const std::string& s) {
    std::string out = s;
    for (char& c : out)
        if (c >= 'A' && c <= 'Z') c = static_cast<char>(c - 'A' + 'a');
    return out;
}
}  // namespace

int Program::findBody(const std::string& name) const {
    const std::string key = lower(name);
    for (size_t i = 0; i < bodies.size(); ++i)
        if (bodies[i].name == key) return static_cast<int>(i);
    return -1;
}

int Program::defaultBody() const {
    int i = findBody("my_model");
    if (i >= 0) return i;
    return bodies.empty() ? -1 : 0;
}

}  // namespace hg::frep
