#include "garden/sculpt/edit_names.h"

#include <nlohmann/json.hpp>

#include "garden/scene/json_reader.h"

namespace hg::garden {

namespace {

// The value among `count` enumerators whose name(i) is the JSON string.
template <class E, class Name>
E readEnum(const nlohmann::json& v, const std::string& path, int count, Name name) {
    const std::string word = readString(v, path);
    std::string expected;
    for (int i = 0; i < count; ++i) {
        if (word == name(static_cast<E>(i))) return static_cast<E>(i);
        expected += (i == 0 ? "" : i + 1 == count ? " or " : ", ") + std::string(name(static_cast<E>(i)));
    }
    throw JsonError(path, "expected " + expected);
}

}  // namespace

const char* strokeToolName(StrokeTool t) {
    switch (t) {
        case StrokeTool::Carve: return "carve";
        case StrokeTool::Add: return "add";
        case StrokeTool::Melt: return "melt";
        case StrokeTool::Smooth: return "smooth";
        case StrokeTool::Inflate: return "inflate";
    }
    return "?";
}

const char* falloffName(Falloff f) {
    switch (f) {
        case Falloff::Smooth: return "smooth";
        case Falloff::Linear: return "linear";
        case Falloff::Sharp: return "sharp";
        case Falloff::Constant: return "constant";
    }
    return "?";
}

const char* sketchModeName(SketchMode m) { return m == SketchMode::Add ? "add" : "cut"; }

const char* impactShapeName(ImpactShape s) {
    switch (s) {
        case ImpactShape::Sphere: return "sphere";
        case ImpactShape::Chisel: return "chisel";
        case ImpactShape::Square: return "square";
    }
    return "?";
}

const char* quadricShapeName(QuadricShape s) { return s == QuadricShape::Ellipsoid ? "ellipsoid" : "torus"; }

const char* impactSpreadName(ImpactSpread s) {
    switch (s) {
        case ImpactSpread::Uniform: return "uniform";
        case ImpactSpread::Gaussian: return "gaussian";
        case ImpactSpread::Cone: return "cone";
    }
    return "?";
}

StrokeTool readStrokeTool(const nlohmann::json& v, const std::string& path) {
    return readEnum<StrokeTool>(v, path, 5, strokeToolName);
}
Falloff readFalloff(const nlohmann::json& v, const std::string& path) {
    return readEnum<Falloff>(v, path, 4, falloffName);
}
QuadricShape readQuadricShape(const nlohmann::json& v, const std::string& path) {
    return readEnum<QuadricShape>(v, path, 2, quadricShapeName);
}
SketchMode readSketchMode(const nlohmann::json& v, const std::string& path) {
    return readEnum<SketchMode>(v, path, 2, sketchModeName);
}
ImpactShape readImpactShape(const nlohmann::json& v, const std::string& path) {
    return readEnum<ImpactShape>(v, path, 3, impactShapeName);
}
ImpactSpread readImpactSpread(const nlohmann::json& v, const std::string& path) {
    return readEnum<ImpactSpread>(v, path, 3, impactSpreadName);
}

}  // namespace hg::garden
