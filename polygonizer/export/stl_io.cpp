#include "polygonizer/export/stl_io.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_pipeline.h>
#include <tbb/parallel_reduce.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <functional>
#include <limits>
#include <memory>
#include <mutex>
#include <string_view>
#include <vector>

#include "io/checked_write.h"

namespace hg::poly {

namespace {

static_assert(std::numeric_limits<float>::is_iec559 && sizeof(float) == 4, "STL stores IEEE 754 binary32");

constexpr std::size_t kHeaderBytes = 80;
constexpr std::size_t kFacetBytes = 50;
// Our binary header; it must not start with "solid", which would make
// naive readers take the file for ASCII.
constexpr std::string_view kHeaderPrefix = "Hypergarden STL: ";

// ---------------------------------------------------------------- writing

// Facets are formatted a slice at a time on TBB workers and written in
// order as each slice is ready: the file is written while later slices are
// formatted, and only a few slices are in memory at once. A binary slice is
// 800 KiB, an ASCII one about 4 MiB.
constexpr std::size_t kSliceFacets = std::size_t{1} << 14;
constexpr std::size_t kCheckGrain = std::size_t{1} << 16;  // indices or coordinates per task of the checks

// How many i in [0, n) have is(i), on TBB. Counted in blocks of a fixed
// length with no early exit, so the compiler vectorizes the inner loop.
template <class Is>
std::size_t countOnThreads(std::size_t n, Is is) {
    return tbb::parallel_reduce(
        tbb::blocked_range<std::size_t>(0, n, kCheckGrain), std::size_t{0},
        [&](const tbb::blocked_range<std::size_t>& r, std::size_t count) {
            constexpr std::size_t kBlock = 64;
            std::size_t i = r.begin();
            for (; i + kBlock <= r.end(); i += kBlock) {
                unsigned block = 0;
                for (std::size_t j = 0; j < kBlock; ++j) block += is(i + j) ? 1u : 0u;
                count += block;
            }
            for (; i < r.end(); ++i) count += is(i) ? 1 : 0;
            return count;
        },
        std::plus<>());
}

// Little-endian whatever the host; the compiler makes one store of it.
char* putU32(char* out, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) out[i] = static_cast<char>((v >> (8 * i)) & 0xffu);
    return out + 4;
}

char* putF32(char* out, float f) {
    std::uint32_t bits;
    std::memcpy(&bits, &f, sizeof bits);
    return putU32(out, bits);
}

void putNumber(std::string& out, float f) {
    // Shortest text that reads back as the same float, whatever the locale.
    char buf[32];
    auto res = std::to_chars(buf, buf + sizeof buf, f);
    out.append(buf, res.ptr);
}

float scaled(float x, double scale) { return static_cast<float>(static_cast<double>(x) * scale); }

// The three scaled corners of a triangle and its unit normal (zero for a
// triangle without area).
struct Facet {
    float v[3][3];
    float n[3];
};

// Facets a group at a time, stage by stage: the square roots and divisions
// of one facet's normal wait on each other, those of different facets do
// not, and a loop over the group lets the processor overlap them.
constexpr std::size_t kFacetGroup = 16;

void facets(const Mesh& mesh, double scale, std::size_t first, std::size_t count, Facet* out) {
    double n[kFacetGroup][3], len[kFacetGroup];
    for (std::size_t g = 0; g < count; ++g) {
        Facet& f = out[g];
        const std::uint32_t* tri = &mesh.indices[3 * (first + g)];
        for (int k = 0; k < 3; ++k)
            for (int a = 0; a < 3; ++a) f.v[k][a] = scaled(mesh.positions[3 * std::size_t{tri[k]} + a], scale);
        double e1[3], e2[3];
        for (int a = 0; a < 3; ++a) {
            e1[a] = static_cast<double>(f.v[1][a]) - static_cast<double>(f.v[0][a]);
            e2[a] = static_cast<double>(f.v[2][a]) - static_cast<double>(f.v[0][a]);
        }
        n[g][0] = e1[1] * e2[2] - e1[2] * e2[1];
        n[g][1] = e1[2] * e2[0] - e1[0] * e2[2];
        n[g][2] = e1[0] * e2[1] - e1[1] * e2[0];
    }
    for (std::size_t g = 0; g < count; ++g)
        len[g] = std::sqrt(n[g][0] * n[g][0] + n[g][1] * n[g][1] + n[g][2] * n[g][2]);
    for (std::size_t g = 0; g < count; ++g) {
        const bool area = len[g] > 0 && std::isfinite(len[g]);
        for (int a = 0; a < 3; ++a) out[g].n[a] = area ? static_cast<float>(n[g][a] / len[g]) : 0.0f;
    }
}

// Calls f(facet) for facets begin..end in order.
template <class F>
void forFacets(const Mesh& mesh, double scale, std::size_t begin, std::size_t end, F f) {
    Facet group[kFacetGroup];
    for (std::size_t t = begin; t < end; t += kFacetGroup) {
        const std::size_t count = std::min(kFacetGroup, end - t);
        facets(mesh, scale, t, count, group);
        for (std::size_t g = 0; g < count; ++g) f(group[g]);
    }
}

void formatBinary(const Mesh& mesh, double scale, std::size_t begin, std::size_t end, std::string& out) {
    out.resize((end - begin) * kFacetBytes);
    char* p = out.data();
    forFacets(mesh, scale, begin, end, [&p](const Facet& f) {
        for (float x : f.n) p = putF32(p, x);
        for (const auto& v : f.v)
            for (float x : v) p = putF32(p, x);
        *p++ = '\0';  // attribute byte count: unused
        *p++ = '\0';
    });
}

void formatAscii(const Mesh& mesh, double scale, std::size_t begin, std::size_t end, std::string& out) {
    out.clear();
    forFacets(mesh, scale, begin, end, [&out](const Facet& f) {
        out += "  facet normal ";
        for (int a = 0; a < 3; ++a) {
            putNumber(out, f.n[a]);
            out += a < 2 ? " " : "\n    outer loop\n";
        }
        for (int k = 0; k < 3; ++k) {
            out += "      vertex ";
            for (int a = 0; a < 3; ++a) {
                putNumber(out, f.v[k][a]);
                out += a < 2 ? ' ' : '\n';
            }
        }
        out += "    endloop\n  endfacet\n";
    });
}

// A name on the "solid" line must stay on that line.
std::string sanitizeName(const std::string& name) {
    std::string s = name;
    for (char& c : s)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '_';
    return s;
}

class File {
public:
    File(const std::string& path, const char* mode) : f_(std::fopen(path.c_str(), mode)) {}
    ~File() {
        if (f_) std::fclose(f_);
    }
    File(const File&) = delete;
    File& operator=(const File&) = delete;
    std::FILE* get() const { return f_; }
    // Closes now, so that a failed flush is seen.
    bool close() {
        std::FILE* f = f_;
        f_ = nullptr;
        return std::fclose(f) == 0;
    }

private:
    std::FILE* f_;
};

// Slice buffers handed from the writing stage back to the formatting one,
// so their pages are touched once, not once per slice.
class BufferPool {
public:
    std::shared_ptr<std::string> take() {
        std::lock_guard<std::mutex> lock(mutex_);
        if (free_.empty()) return std::make_shared<std::string>();
        std::shared_ptr<std::string> b = std::move(free_.back());
        free_.pop_back();
        return b;
    }
    void give(std::shared_ptr<std::string> b) {
        std::lock_guard<std::mutex> lock(mutex_);
        free_.push_back(std::move(b));
    }

private:
    std::mutex mutex_;
    std::vector<std::shared_ptr<std::string>> free_;
};

struct Slice {
    std::size_t begin = 0, end = 0;
    std::shared_ptr<std::string> text;
};

std::string writeContents(const Mesh& mesh, double scale, const std::string& tmp, const std::string& path, bool ascii,
                          const std::string& name) {
    io::CheckedFile file(tmp, io::WriteSite::Export);
    const std::string cannot = "cannot write " + path + ": ";
    if (!file.ok()) return file.error();
    auto put = [&file](const std::string& bytes) {
        file.write(bytes);
        return file.ok();
    };
    const std::size_t triangles = mesh.triangleCount();

    std::string head;
    if (ascii) {
        head = name.empty() ? "solid\n" : "solid " + name + "\n";
    } else {
        head = std::string(kHeaderPrefix) + name;
        head.resize(kHeaderBytes, '\0');
        head.resize(kHeaderBytes + 4);
        putU32(&head[kHeaderBytes], static_cast<std::uint32_t>(triangles));
    }
    put(head);

    BufferPool pool;
    std::size_t next = 0;
    std::atomic<bool> error{!file.ok()};  // a write failed: no slice is started or written after it
    const auto tokens = static_cast<std::size_t>(2 * std::max(1, tbb::this_task_arena::max_concurrency()));
    tbb::parallel_pipeline(
        tokens,
        tbb::make_filter<void, Slice>(tbb::filter_mode::serial_in_order,
                                      [&](tbb::flow_control& fc) {
                                          Slice s;
                                          if (next == triangles || error) {
                                              fc.stop();
                                              return s;
                                          }
                                          s.begin = next;
                                          s.end = next = std::min(triangles, next + kSliceFacets);
                                          return s;
                                      }) &
            tbb::make_filter<Slice, Slice>(tbb::filter_mode::parallel,
                                           [&](Slice s) {
                                               s.text = pool.take();
                                               if (ascii)
                                                   formatAscii(mesh, scale, s.begin, s.end, *s.text);
                                               else
                                                   formatBinary(mesh, scale, s.begin, s.end, *s.text);
                                               return s;
                                           }) &
            tbb::make_filter<Slice, void>(tbb::filter_mode::serial_in_order, [&](Slice s) {
                if (!error && !put(*s.text)) error = true;
                pool.give(std::move(s.text));
            }));
    if (ascii && !error) put(name.empty() ? "endsolid\n" : "endsolid " + name + "\n");
    if (std::string why = file.finish(); !why.empty()) return cannot + why;
    return "";
}

// ---------------------------------------------------------------- reading

std::uint32_t getU32(const unsigned char* p) {
    return std::uint32_t{p[0]} | std::uint32_t{p[1]} << 8 | std::uint32_t{p[2]} << 16 | std::uint32_t{p[3]} << 24;
}

float getF32(const unsigned char* p) {
    const std::uint32_t bits = getU32(p);
    float f;
    std::memcpy(&f, &bits, sizeof f);
    return f;
}

bool readAll(const std::string& path, std::string& data, std::string& error) {
    File file(path, "rb");
    if (!file.get()) {
        error = "cannot open " + path + ": " + std::strerror(errno);
        return false;
    }
    char buf[1 << 16];
    std::size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, file.get())) > 0) data.append(buf, n);
    if (std::ferror(file.get())) {
        error = "cannot read " + path + ": " + std::strerror(errno);
        return false;
    }
    return true;
}

bool startsWithSolid(const std::string& data) {
    std::size_t i = 0;
    while (i < data.size() && std::isspace(static_cast<unsigned char>(data[i]))) ++i;
    if (data.size() - i < 5) return false;
    for (std::size_t k = 0; k < 5; ++k)
        if (std::tolower(static_cast<unsigned char>(data[i + k])) != "solid"[k]) return false;
    return i + 5 == data.size() || std::isspace(static_cast<unsigned char>(data[i + 5]));
}

void readBinary(const std::string& data, std::uint32_t count, StlReadResult& r) {
    const auto* bytes = reinterpret_cast<const unsigned char*>(data.data());
    std::string header(data.data(), kHeaderBytes);
    header.resize(std::strlen(header.c_str()));
    while (!header.empty() && std::isspace(static_cast<unsigned char>(header.back()))) header.pop_back();
    if (header.compare(0, kHeaderPrefix.size(), kHeaderPrefix) == 0) header.erase(0, kHeaderPrefix.size());
    r.solidName = header;

    r.mesh.positions.reserve(9 * std::size_t{count});
    r.mesh.indices.reserve(3 * std::size_t{count});
    for (std::size_t t = 0; t < count; ++t) {
        const unsigned char* p = bytes + kHeaderBytes + 4 + kFacetBytes * t + 12;  // past the normal
        for (int k = 0; k < 9; ++k) r.mesh.positions.push_back(getF32(p + 4 * k));
        for (int k = 0; k < 3; ++k) r.mesh.indices.push_back(static_cast<std::uint32_t>(3 * t + k));
    }
}

// Whitespace-separated words with their line numbers.
class Lexer {
public:
    explicit Lexer(std::string_view text) : p_(text.data()), end_(text.data() + text.size()) {}

    bool next(std::string_view& word) {
        skipSpace();
        if (p_ == end_) return false;
        const char* start = p_;
        while (p_ != end_ && !std::isspace(static_cast<unsigned char>(*p_))) ++p_;
        word = std::string_view(start, static_cast<std::size_t>(p_ - start));
        wordLine_ = line_;
        return true;
    }

    // The rest of the current line, trimmed; the next word starts after it.
    std::string restOfLine() {
        const char* start = p_;
        while (p_ != end_ && *p_ != '\n') ++p_;
        std::string_view s(start, static_cast<std::size_t>(p_ - start));
        while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
        while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
        return std::string(s);
    }

    std::size_t wordLine() const { return wordLine_; }
    std::size_t line() const { return line_; }

private:
    void skipSpace() {
        for (; p_ != end_ && std::isspace(static_cast<unsigned char>(*p_)); ++p_)
            if (*p_ == '\n') ++line_;
    }

    const char* p_;
    const char* end_;
    std::size_t line_ = 1;
    std::size_t wordLine_ = 1;
};

bool keyword(std::string_view word, std::string_view expected) {
    if (word.size() != expected.size()) return false;
    for (std::size_t i = 0; i < word.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(word[i])) != expected[i]) return false;
    return true;
}

// For messages: short, and printable even when the file is not text.
std::string quote(std::string_view word) {
    std::string s = "'";
    for (std::size_t i = 0; i < word.size() && i < 24; ++i) {
        const auto c = static_cast<unsigned char>(word[i]);
        s += std::isprint(c) ? static_cast<char>(c) : '?';
    }
    return s + (word.size() > 24 ? "...'" : "'");
}

bool parseFloat(std::string_view word, float& out) {
    if (!word.empty() && word.front() == '+') word.remove_prefix(1);
    const char* first = word.data();
    const char* last = first + word.size();
    auto res = std::from_chars(first, last, out);
    if (res.ec == std::errc::result_out_of_range) {
        // Values below float's range are zero (or subnormal) to a printer;
        // values above it are an error.
        double d;
        auto wide = std::from_chars(first, last, d);
        if (wide.ec != std::errc() || wide.ptr != last || !(std::fabs(d) < 1.0)) return false;
        out = static_cast<float>(d);
        return true;
    }
    return res.ec == std::errc() && res.ptr == last;
}

class AsciiParser {
public:
    AsciiParser(std::string_view text, const std::string& path, StlReadResult& r) : lex_(text), path_(path), r_(r) {}

    bool run() {
        std::string_view w;
        if (!lex_.next(w) || !keyword(w, "solid")) return fail("expected 'solid'", w);
        r_.solidName = lex_.restOfLine();
        while (true) {
            if (!lex_.next(w)) return failAtEnd("expected 'endsolid'");
            if (keyword(w, "endsolid")) {
                lex_.restOfLine();
                // Some exporters write one solid per part into a file.
                if (!lex_.next(w)) return true;
                if (!keyword(w, "solid")) return fail("expected 'solid' or the end of the file", w);
                lex_.restOfLine();
                continue;
            }
            if (!keyword(w, "facet")) return fail("expected 'facet' or 'endsolid'", w);
            float normal[3];
            if (!expect("normal") || !numbers(normal) || !expect("outer") || !expect("loop")) return false;
            for (int k = 0; k < 3; ++k) {
                float v[3];
                if (!expect("vertex") || !numbers(v)) return false;
                r_.mesh.positions.insert(r_.mesh.positions.end(), v, v + 3);
            }
            if (!expect("endloop") || !expect("endfacet")) return false;
            if (r_.mesh.indices.size() + 3 > std::numeric_limits<std::uint32_t>::max())
                return failAtEnd("too many facets for 32-bit indices");
            for (int k = 0; k < 3; ++k)
                r_.mesh.indices.push_back(static_cast<std::uint32_t>(r_.mesh.indices.size()));
        }
    }

private:
    bool expect(std::string_view kw) {
        std::string_view w;
        if (!lex_.next(w)) return failAtEnd("expected '" + std::string(kw) + "'");
        if (!keyword(w, kw)) return fail("expected '" + std::string(kw) + "'", w);
        return true;
    }

    bool numbers(float (&out)[3]) {
        for (float& x : out) {
            std::string_view w;
            if (!lex_.next(w)) return failAtEnd("expected a number");
            if (!parseFloat(w, x)) return fail("expected a number", w);
        }
        return true;
    }

    bool fail(const std::string& what, std::string_view found) {
        r_.error = path_ + ": line " + std::to_string(lex_.wordLine()) + ": " + what +
                   (found.empty() ? std::string() : ", found " + quote(found));
        return false;
    }

    bool failAtEnd(const std::string& what) {
        r_.error = path_ + ": line " + std::to_string(lex_.line()) + ": " + what + ", but the file ends";
        return false;
    }

    Lexer lex_;
    const std::string& path_;
    StlReadResult& r_;
};

}  // namespace

std::string writeStl(const Mesh& mesh, const std::string& path, bool ascii, double scale,
                     const std::string& solidName) {
    if (path.empty()) return "no output file given";
    const std::string cannot = "cannot write " + path + ": ";
    if (!(scale > 0) || !std::isfinite(scale)) return cannot + "the scale must be positive and finite";
    if (mesh.indices.size() % 3 != 0) return cannot + "the mesh's index count is not a multiple of three";
    if (!ascii && mesh.triangleCount() > std::numeric_limits<std::uint32_t>::max())
        return cannot + "too many triangles for binary STL";

    // Checked before the file is opened, on all threads: an index out of
    // range, or the first vertex that is not finite once scaled.
    if (mesh.vertexCount() <= std::numeric_limits<std::uint32_t>::max()) {
        const auto limit = static_cast<std::uint32_t>(mesh.vertexCount());
        const std::uint32_t* indices = mesh.indices.data();
        if (countOnThreads(mesh.indices.size(), [indices, limit](std::size_t i) { return indices[i] >= limit; }) > 0)
            return cannot + "the mesh has an index out of range";
    }
    const float* positions = mesh.positions.data();
    auto notFinite = [positions, scale](std::size_t i) { return !std::isfinite(scaled(positions[i], scale)); };
    if (countOnThreads(mesh.positions.size(), notFinite) > 0) {
        std::size_t i = 0;
        while (!notFinite(i)) ++i;
        return cannot + "vertex " + std::to_string(i / 3) + " is not finite";
    }

    return io::writeAtomically(path, io::WriteSite::Export, [&](const std::string& tmp) {
        return writeContents(mesh, scale, tmp, path, ascii, sanitizeName(solidName));
    });
}

StlReadResult readStl(const std::string& path) {
    StlReadResult r;
    std::string data;
    if (!readAll(path, data, r.error)) return r;

    // ASCII STL has no NUL bytes and binary nearly always has some (in the
    // attribute bytes if nowhere else): a binary file of the wrong size is
    // reported as such even when its header starts with "solid", rather
    // than as a puzzling ASCII syntax error.
    const bool solid = startsWithSolid(data);
    const bool text = data.find('\0') == std::string::npos;
    const std::string size = std::to_string(data.size()) + " bytes";
    if (data.size() >= kHeaderBytes + 4) {
        const std::uint32_t count = getU32(reinterpret_cast<const unsigned char*>(data.data()) + kHeaderBytes);
        const std::uint64_t expected = kHeaderBytes + 4 + std::uint64_t{kFacetBytes} * count;
        if (data.size() == expected) {
            readBinary(data, count, r);
            return r;
        }
        if (!(solid && text)) {
            if (text)
                r.error = path + ": not an STL file: it does not start with 'solid' and its size (" + size +
                          ") does not match a binary STL's triangle count";
            else
                r.error = path + ": " + (data.size() < expected ? "truncated" : "malformed") +
                          " binary STL: the header says " + std::to_string(count) + " triangles (" +
                          std::to_string(expected) + " bytes) but the file has " + size;
            return r;
        }
    } else if (!(solid && text)) {
        r.error = path + ": " +
                  (text ? "not an STL file: it does not start with 'solid' and is too short for binary STL (" + size +
                              ")"
                        : "truncated binary STL: " + size + ", less than the 84-byte header and count");
        return r;
    }

    r.ascii = true;
    if (!AsciiParser(data, path, r).run()) r.mesh = Mesh{};
    return r;
}

}  // namespace hg::poly
