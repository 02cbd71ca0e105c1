#include "garden/scene/model_file.h"

#include "frep/language/parser.h"

namespace hg::garden {

int findBodyOrExplain(const frep::Program& program, const std::string& name, const std::string& file,
                      std::string& why) {
    int body = name.empty() ? program.defaultBody() : program.findBody(name);
    if (body >= 0) return body;
    why = file + ": error: no body named '" + name + "'; the file defines:";
    for (const auto& b : program.bodies) why += " " + b.spelling;
    why += "\n";
    return -1;
}

namespace {

ModelFile modelFrom(frep::ParseResult parsed, const std::string& label, const std::string& body,
                    const std::vector<double>& a) {
    ModelFile mf;
    for (const auto& d : parsed.errors) mf.error += frep::formatDiagnostic(d);
    if (!parsed.ok()) return mf;
    mf.program = std::make_shared<const frep::Program>(std::move(*parsed.program));
    int index = findBodyOrExplain(*mf.program, body, label, mf.error);
    if (index < 0) return mf;
    mf.model.emplace(mf.program, index, a);
    return mf;
}

}  // namespace

ModelFile loadModelFile(const std::string& path, const std::string& body, const std::vector<double>& a) {
    return modelFrom(frep::parseFile(path), path, body, a);
}

ModelFile modelFromText(const std::string& text, const std::string& label, const std::string& body,
                        const std::vector<double>& a) {
    return modelFrom(frep::parseProgram(text, label), label, body, a);
}

}  // namespace hg::garden
