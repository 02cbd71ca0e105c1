#include "polygonizer/export/mesh_read.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <string_view>
#include <vector>

#include "io/read_text.h"
#include "polygonizer/export/mesh_validation.h"
#include "polygonizer/export/stl_io.h"

namespace hg::poly {

namespace {

// Whitespace-separated words of one line.
std::vector<std::string_view> words(std::string_view line) {
    std::vector<std::string_view> out;
    std::size_t i = 0;
    while (i < line.size()) {
        while (i < line.size() && std::isspace(static_cast<unsigned char>(line[i]))) ++i;
        const std::size_t start = i;
        while (i < line.size() && !std::isspace(static_cast<unsigned char>(line[i]))) ++i;
        if (i > start) out.push_back(line.substr(start, i - start));
    }
    return out;
}

bool toDouble(std::string_view w, double& out) {
    if (!w.empty() && w.front() == '+') w.remove_prefix(1);
    const auto r = std::from_chars(w.data(), w.data() + w.size(), out);
    return r.ec == std::errc() && r.ptr == w.data() + w.size() && std::isfinite(out);
}

bool toLong(std::string_view w, long long& out) {
    if (!w.empty() && w.front() == '+') w.remove_prefix(1);
    const auto r = std::from_chars(w.data(), w.data() + w.size(), out);
    return r.ec == std::errc() && r.ptr == w.data() + w.size();
}

std::string shown(std::string_view w) {
    std::string s;
    for (std::size_t i = 0; i < w.size() && i < 24; ++i) {
        const auto c = static_cast<unsigned char>(w[i]);
        s += std::isprint(c) ? static_cast<char>(c) : '?';
    }
    return "'" + s + (w.size() > 24 ? "...'" : "'");
}

// Splits `text` into lines, with their numbers from 1 (a '\r' before the
// '\n' is dropped).
template <typename Each>
bool forEachLine(std::string_view text, Each each) {
    std::size_t line = 0, at = 0;
    while (at < text.size()) {
        std::size_t end = text.find('\n', at);
        if (end == std::string_view::npos) end = text.size();
        std::string_view l = text.substr(at, end - at);
        if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
        if (!each(++line, l)) return false;
        at = end + 1;
    }
    return true;
}

bool addPosition(Mesh& mesh, const double (&p)[3]) {
    for (double x : p)
        if (!(std::fabs(x) <= static_cast<double>(std::numeric_limits<float>::max()))) return false;
    for (double x : p) mesh.positions.push_back(static_cast<float>(x));
    return true;
}

// A polygon's corners as a fan from the first corner.
void addFan(Mesh& mesh, const std::vector<std::uint32_t>& corners) {
    for (std::size_t k = 1; k + 1 < corners.size(); ++k) {
        mesh.indices.push_back(corners[0]);
        mesh.indices.push_back(corners[k]);
        mesh.indices.push_back(corners[k + 1]);
    }
}

std::string emptyMesh(const std::string& path) { return path + ": the mesh has no triangles"; }

// ---- PLY -------------------------------------------------------------------

enum class PlyType { I8, U8, I16, U16, I32, U32, F32, F64 };

bool plyType(std::string_view name, PlyType& t) {
    static const std::pair<const char*, PlyType> kTypes[] = {
        {"char", PlyType::I8},    {"int8", PlyType::I8},     {"uchar", PlyType::U8},   {"uint8", PlyType::U8},
        {"short", PlyType::I16},  {"int16", PlyType::I16},   {"ushort", PlyType::U16}, {"uint16", PlyType::U16},
        {"int", PlyType::I32},    {"int32", PlyType::I32},   {"uint", PlyType::U32},   {"uint32", PlyType::U32},
        {"float", PlyType::F32},  {"float32", PlyType::F32}, {"double", PlyType::F64}, {"float64", PlyType::F64}};
    for (const auto& [n, type] : kTypes)
        if (name == n) {
            t = type;
            return true;
        }
    return false;
}

std::size_t plySize(PlyType t) {
    switch (t) {
        case PlyType::I8: case PlyType::U8: return 1;
        case PlyType::I16: case PlyType::U16: return 2;
        case PlyType::I32: case PlyType::U32: case PlyType::F32: return 4;
        case PlyType::F64: return 8;
    }
    return 1;
}

struct PlyProperty {
    std::string name;
    PlyType type = PlyType::F32;
    bool list = false;
    PlyType countType = PlyType::U8;
};

struct PlyElement {
    std::string name;
    std::uint64_t count = 0;
    std::vector<PlyProperty> properties;
};

// The body after the header: ASCII words line by line, or little-endian
// values byte by byte; either way one value at a time, and where it is.
class PlyBody {
public:
    PlyBody(std::string_view body, bool ascii, std::size_t headerBytes, std::size_t headerLines)
        : body_(body), ascii_(ascii), headerBytes_(headerBytes), line_(headerLines) {}

    bool value(PlyType t, double& out) {
        if (ascii_) {
            while (word_ >= words_.size()) {
                if (at_ >= body_.size()) return false;
                std::size_t end = body_.find('\n', at_);
                if (end == std::string_view::npos) end = body_.size();
                words_ = words(body_.substr(at_, end - at_));
                word_ = 0;
                at_ = end + 1;
                ++line_;
            }
            const std::string_view w = words_[word_++];
            if (!toDouble(w, out)) {
                bad_ = "expected a number, found " + shown(w);
                return false;
            }
            return true;
        }
        const std::size_t n = plySize(t);
        if (at_ + n > body_.size()) return false;
        unsigned char b[8];
        std::memcpy(b, body_.data() + at_, n);
        at_ += n;
        std::uint64_t u = 0;
        for (std::size_t i = 0; i < n; ++i) u |= std::uint64_t{b[i]} << (8 * i);
        switch (t) {
            case PlyType::I8: out = static_cast<std::int8_t>(u); break;
            case PlyType::U8: case PlyType::U16: case PlyType::U32: out = static_cast<double>(u); break;
            case PlyType::I16: out = static_cast<std::int16_t>(u); break;
            case PlyType::I32: out = static_cast<std::int32_t>(u); break;
            case PlyType::F32: {
                float f;
                const auto u32 = static_cast<std::uint32_t>(u);
                std::memcpy(&f, &u32, 4);
                out = f;
                break;
            }
            case PlyType::F64: std::memcpy(&out, &u, 8); break;
        }
        if (!std::isfinite(out)) {
            bad_ = "a value that is not a finite number";
            return false;
        }
        return true;
    }

    // Where the value being read is: "x.ply:12" or "x.ply: byte 345".
    std::string where(const std::string& path) const {
        if (ascii_) return path + ":" + std::to_string(line_);
        return path + ": byte " + std::to_string(headerBytes_ + at_);
    }
    // Why value() said no: a bad word, else the end of the file.
    std::string why(const std::string& what) const {
        return bad_.empty() ? what + ", but the file ends" : bad_ + " (" + what + ")";
    }

private:
    std::string_view body_;
    bool ascii_;
    std::size_t headerBytes_;
    std::size_t at_ = 0;
    std::size_t line_;
    std::vector<std::string_view> words_;
    std::size_t word_ = 0;
    std::string bad_;
};

}  // namespace

MeshReadResult readObj(const std::string& path) {
    MeshReadResult r;
    std::string text;
    if (std::string why = io::readText(path, text); !why.empty()) {
        r.error = "cannot read " + why;
        return r;
    }
    std::vector<std::uint32_t> corners;
    const auto fail = [&](std::size_t line, const std::string& what) {
        r.error = path + ":" + std::to_string(line) + ": " + what;
        return false;
    };
    const bool ok = forEachLine(text, [&](std::size_t line, std::string_view l) {
        const std::vector<std::string_view> w = words(l);
        if (w.empty() || w[0].front() == '#') return true;
        if (w[0] == "v") {
            if (w.size() < 4) return fail(line, "a vertex needs x, y and z");
            double p[3];
            for (int a = 0; a < 3; ++a)
                if (!toDouble(w[static_cast<std::size_t>(a) + 1], p[a]))
                    return fail(line, "expected a number, found " + shown(w[static_cast<std::size_t>(a) + 1]));
            if (!addPosition(r.mesh, p)) return fail(line, "a vertex coordinate is beyond a float's range");
            return true;
        }
        if (w[0] != "f") return true;
        if (w.size() < 4) return fail(line, "a face needs at least 3 corners, found " + std::to_string(w.size() - 1));
        const long long count = static_cast<long long>(r.mesh.vertexCount());
        corners.clear();
        for (std::size_t k = 1; k < w.size(); ++k) {
            const std::string_view v = w[k].substr(0, w[k].find('/'));
            long long index = 0;
            if (!toLong(v, index) || index == 0) return fail(line, "expected a vertex index (1, 2, ... or -1, -2, ...), found " + shown(w[k]));
            const long long zeroBased = index > 0 ? index - 1 : count + index;
            if (zeroBased < 0 || zeroBased >= count)
                return fail(line, "face index " + std::to_string(index) + " out of range (" + std::to_string(count) +
                                      " vertices)");
            corners.push_back(static_cast<std::uint32_t>(zeroBased));
        }
        addFan(r.mesh, corners);
        return true;
    });
    if (!ok) {
        r.mesh = Mesh{};
        return r;
    }
    if (r.mesh.empty()) r.error = emptyMesh(path);
    return r;
}

MeshReadResult readPly(const std::string& path) {
    MeshReadResult r;
    std::string text;
    if (std::string why = io::readText(path, text); !why.empty()) {
        r.error = "cannot read " + why;
        return r;
    }
    // The header: lines up to "end_header".
    std::vector<PlyElement> elements;
    bool ascii = true, formatSeen = false, ended = false;
    std::size_t at = 0, line = 0;
    const auto fail = [&](const std::string& what) {
        r.error = path + ":" + std::to_string(line) + ": " + what;
        return r;
    };
    while (!ended) {
        if (at >= text.size()) return fail("the header has no 'end_header'");
        std::size_t end = text.find('\n', at);
        if (end == std::string::npos) end = text.size();
        std::string_view l(text.data() + at, end - at);
        if (!l.empty() && l.back() == '\r') l.remove_suffix(1);
        at = end + 1;
        ++line;
        const std::vector<std::string_view> w = words(l);
        if (line == 1) {
            if (w.size() != 1 || w[0] != "ply") return fail("not a PLY file: it does not start with 'ply'");
            continue;
        }
        if (w.empty() || w[0] == "comment" || w[0] == "obj_info") continue;
        if (w[0] == "format") {
            if (w.size() != 3) return fail("expected 'format ascii 1.0' or 'format binary_little_endian 1.0'");
            if (w[1] == "binary_little_endian") ascii = false;
            else if (w[1] == "binary_big_endian")
                return fail("binary_big_endian PLY is not read; save it as ascii or binary_little_endian");
            else if (w[1] != "ascii") return fail("unknown PLY format " + shown(w[1]));
            formatSeen = true;
        } else if (w[0] == "element") {
            long long count = 0;
            if (w.size() != 3 || !toLong(w[2], count) || count < 0)
                return fail("expected 'element NAME COUNT'");
            // Every element takes a byte at least: a count past the file's size is a lie.
            if (static_cast<unsigned long long>(count) > text.size())
                return fail("element '" + std::string(w[1]) + "' claims " + std::to_string(count) +
                            " items, more than the file's " + std::to_string(text.size()) + " bytes can hold");
            elements.push_back({std::string(w[1]), static_cast<std::uint64_t>(count), {}});
        } else if (w[0] == "property") {
            if (elements.empty()) return fail("a property before any element");
            PlyProperty p;
            if (w.size() == 5 && w[1] == "list") {
                p.list = true;
                if (!plyType(w[2], p.countType) || !plyType(w[3], p.type)) return fail("unknown type in " + shown(l));
                p.name = std::string(w[4]);
            } else if (w.size() == 3) {
                if (!plyType(w[1], p.type)) return fail("unknown type " + shown(w[1]));
                p.name = std::string(w[2]);
            } else {
                return fail("expected 'property TYPE NAME' or 'property list COUNT_TYPE TYPE NAME'");
            }
            elements.back().properties.push_back(p);
        } else if (w[0] == "end_header") {
            ended = true;
        } else {
            return fail("unknown header line " + shown(l));
        }
    }
    if (!formatSeen) return fail("the header has no 'format' line");
    const std::size_t headerLines = line;
    PlyBody body(std::string_view(text).substr(std::min(at, text.size())), ascii, at, headerLines);
    bool sawVertex = false, sawFace = false;
    std::vector<std::uint32_t> corners;
    for (const PlyElement& e : elements) {
        const bool isVertex = e.name == "vertex", isFace = e.name == "face";
        int xyz[3] = {-1, -1, -1};
        int indexList = -1;
        for (std::size_t k = 0; k < e.properties.size(); ++k) {
            const PlyProperty& p = e.properties[k];
            if (isVertex && !p.list && p.name.size() == 1 && p.name[0] >= 'x' && p.name[0] <= 'z')
                xyz[p.name[0] - 'x'] = static_cast<int>(k);
            if (isFace && p.list && (p.name == "vertex_indices" || p.name == "vertex_index")) indexList = static_cast<int>(k);
        }
        if (isVertex) {
            sawVertex = true;
            if (xyz[0] < 0 || xyz[1] < 0 || xyz[2] < 0) return fail("the vertex element has no x, y and z properties");
        }
        if (isFace) {
            sawFace = true;
            if (indexList < 0) return fail("the face element has no 'vertex_indices' list");
        }
        for (std::uint64_t item = 0; item < e.count; ++item) {
            double p[3] = {0, 0, 0};
            corners.clear();
            for (std::size_t k = 0; k < e.properties.size(); ++k) {
                const PlyProperty& prop = e.properties[k];
                const std::string what = e.name + " " + std::to_string(item) + "'s " + prop.name;
                double v = 0;
                if (!prop.list) {
                    if (!body.value(prop.type, v)) {
                        r.error = body.where(path) + ": " + body.why("expected " + what);
                        return r;
                    }
                    for (int a = 0; a < 3; ++a)
                        if (xyz[a] == static_cast<int>(k)) p[a] = v;
                    continue;
                }
                double n = 0;
                if (!body.value(prop.countType, n)) {
                    r.error = body.where(path) + ": " + body.why("expected the count of " + what);
                    return r;
                }
                if (n < 0 || n != std::floor(n) || n > 1e6) {
                    r.error = body.where(path) + ": " + what + " has a bad count";
                    return r;
                }
                const bool corner = static_cast<int>(k) == indexList;
                if (corner && n < 3) {
                    r.error = body.where(path) + ": face " + std::to_string(item) + " has " +
                              std::to_string(static_cast<int>(n)) + " corners; a face needs at least 3";
                    return r;
                }
                for (int c = 0; c < static_cast<int>(n); ++c) {
                    if (!body.value(prop.type, v)) {
                        r.error = body.where(path) + ": " + body.why("expected " + what);
                        return r;
                    }
                    if (!corner) continue;
                    const double count = static_cast<double>(r.mesh.vertexCount());
                    if (v < 0 || v >= count || v != std::floor(v)) {
                        r.error = body.where(path) + ": face index " + std::to_string(static_cast<long long>(v)) +
                                  " out of range (" + std::to_string(r.mesh.vertexCount()) + " vertices)";
                        return r;
                    }
                    corners.push_back(static_cast<std::uint32_t>(v));
                }
            }
            if (isVertex && !addPosition(r.mesh, p)) {
                r.error = body.where(path) + ": vertex " + std::to_string(item) + " is beyond a float's range";
                return r;
            }
            if (isFace) addFan(r.mesh, corners);
        }
    }
    if (!sawVertex || !sawFace) {
        line = headerLines;
        return fail(std::string("the header declares no '") + (sawVertex ? "face" : "vertex") + "' element");
    }
    if (r.mesh.empty()) r.error = emptyMesh(path);
    return r;
}

bool isMeshFileName(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext == ".stl" || ext == ".obj" || ext == ".ply";
}

MeshReadResult readMeshFile(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (ext == ".obj") return readObj(path);
    if (ext == ".ply") return readPly(path);
    MeshReadResult r;
    if (ext != ".stl") {
        r.error = path + ": expected a mesh file (.stl, .obj or .ply)";
        return r;
    }
    StlReadResult stl = readStl(path);
    if (!stl.error.empty()) {
        r.error = stl.error;
        return r;
    }
    // A facet soup: shared corners become shared vertices, so the surface
    // is one piece (and its edges can be checked for being closed).
    r.mesh = weldByPosition(stl.mesh);
    r.mesh.normals.clear();
    if (r.mesh.empty()) r.error = emptyMesh(path);
    return r;
}

}  // namespace hg::poly
