#include "polygonizer/export/obj_io.h"

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>

#include "io/checked_write.h"

namespace hg::poly {

namespace {

// Lines are gathered in a buffer and written a few MiB at a time.
class LineBuffer {
public:
    explicit LineBuffer(io::CheckedFile& f) : file_(f), data_(new char[kSize]) {}

    void text(const char* s) {
        const std::size_t n = std::strlen(s);
        reserve(n);
        std::memcpy(data_.get() + used_, s, n);
        used_ += n;
    }
    void number(float v) {
        reserve(32);
        char* p = data_.get() + used_;
        used_ = static_cast<std::size_t>(std::to_chars(p, p + 32, v).ptr - data_.get());
    }
    void number(std::uint32_t v) {
        reserve(16);
        char* p = data_.get() + used_;
        used_ = static_cast<std::size_t>(std::to_chars(p, p + 16, v).ptr - data_.get());
    }
    void put(char c) {
        reserve(1);
        data_[used_++] = c;
    }
    void flush() {
        file_.write(data_.get(), used_);
        used_ = 0;
    }

private:
    static constexpr std::size_t kSize = std::size_t{4} << 20;
    void reserve(std::size_t n) {
        if (used_ + n > kSize) flush();
    }
    io::CheckedFile& file_;
    std::unique_ptr<char[]> data_;
    std::size_t used_ = 0;
};

std::string writeTo(const Mesh& mesh, const std::string& tmp, const std::string& path, float scale,
                    const std::string& objectName) {
    io::CheckedFile file(tmp, io::WriteSite::Export);
    if (!file.ok()) return file.error();
    LineBuffer out(file);
    out.text("# Hypergarden mesh export: metres, counter-clockwise faces seen from outside\no ");
    out.text(objectName.c_str());
    out.put('\n');
    const std::size_t n = mesh.vertexCount();
    for (std::size_t v = 0; v < n; ++v) {
        out.put('v');
        for (std::size_t a = 0; a < 3; ++a) {
            out.put(' ');
            out.number(mesh.positions[3 * v + a] * scale);
        }
        out.put('\n');
    }
    for (std::size_t v = 0; v < n; ++v) {
        out.text("vn");
        for (std::size_t a = 0; a < 3; ++a) {
            out.put(' ');
            out.number(mesh.normals[3 * v + a]);
        }
        out.put('\n');
    }
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        out.put('f');
        for (std::size_t k = 0; k < 3; ++k) {
            const std::uint32_t i = mesh.indices[3 * t + k] + 1;
            out.put(' ');
            out.number(i);
            out.text("//");
            out.number(i);
        }
        out.put('\n');
    }
    out.flush();
    if (std::string why = file.finish(); !why.empty()) return "cannot write " + path + ": " + why;
    return "";
}

}  // namespace

std::string writeObj(const Mesh& mesh, const std::string& path, double scale, const std::string& objectName) {
    if (!(scale > 0.0) || !std::isfinite(scale)) return "cannot write " + path + ": the scale must be finite and positive";
    if (mesh.normals.size() != mesh.positions.size())
        return "cannot write " + path + ": the mesh has no normal for every vertex";
    const auto s = static_cast<float>(scale);
    // The name stays on its "o" line: a line break in it would start lines of its own.
    std::string name = objectName;
    for (char& c : name)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '_';
    return io::writeAtomically(path, io::WriteSite::Export, [&](const std::string& tmp) { return writeTo(mesh, tmp, path, s, name); });
}

}  // namespace hg::poly
