// The layers of the code (docs/design.md, "Layers"), checked on the source
// tree itself: a folder may include its own headers and those of folders on
// lower layers, never a folder on its own layer or above. So no include runs
// upward and the folders' include graph has no cycle. The list below is the
// one statement of the order; a new folder must be placed in it.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

// Layer per folder, lowest first. Folders on one layer are siblings that
// must not include each other.
const std::map<std::string, int>& layers() {
    static const std::map<std::string, int> l = {
        {"frep/kernels", 0},   {"io", 0}, {"jobs", 0},
        {"frep/language", 1},
        {"frep/compiler", 2},
        {"frep/eval", 3},
        {"voxel", 4},
        {"polygonizer", 5},
        {"polygonizer/realtime", 6}, {"polygonizer/export", 6},
        {"garden/scene", 7},   {"garden/sketch", 7},
        {"garden/sculpt", 8},  {"garden/morph", 8}, {"garden/hands", 8},
        {"garden/gesture", 8}, {"garden/deform", 8},
        {"garden/action", 9},
        {"garden/app", 10},
        {"garden/session", 11}, {"garden/replay", 11}, {"garden/export", 11},
        {"garden/render", 12},
        {"garden/window", 13},
        {"garden/desktop", 14}, {"xr", 14},
        {"xr/mock_runtime", 15},
        {"cli", 16},
    };
    return l;
}

// The folder a source file or an include path belongs to: its directory,
// with frep/kernels/library counted as frep/kernels (the kernels' own
// library of hf* routines).
std::string folderOf(const std::string& path) {
    const std::string dir = fs::path(path).parent_path().generic_string();
    if (dir.rfind("frep/kernels/", 0) == 0) return "frep/kernels";
    return dir;
}

struct Include {
    std::string file;  // relative to the source root
    int line = 0;
    std::string target;
};

std::vector<Include> projectIncludes(const fs::path& root) {
    std::vector<Include> out;
    const std::regex include(R"re(^\s*#\s*include\s+"([^"]+)")re");
    for (const char* top : {"frep", "io", "jobs", "voxel", "polygonizer", "garden", "xr", "cli"}) {
        if (!fs::exists(root / top)) continue;
        for (const auto& entry : fs::recursive_directory_iterator(root / top)) {
            const std::string ext = entry.path().extension().string();
            if (!entry.is_regular_file() || (ext != ".h" && ext != ".cpp")) continue;
            std::ifstream in(entry.path());
            std::string text;
            int n = 0;
            while (std::getline(in, text)) {
                ++n;
                std::smatch m;
                if (std::regex_search(text, m, include) && m[1].str().find('/') != std::string::npos)
                    out.push_back({fs::relative(entry.path(), root).generic_string(), n, m[1].str()});
            }
        }
    }
    return out;
}

TEST(IncludeLayers, EveryFolderHasALayer) {
    const fs::path root = HG_SOURCE_DIR;
    std::set<std::string> unplaced;
    for (const Include& i : projectIncludes(root))
        if (!layers().count(folderOf(i.file))) unplaced.insert(folderOf(i.file));
    EXPECT_TRUE(unplaced.empty()) << "folders with no layer (add them to tests/layers and docs/design.md): "
                                  << [&] {
                                         std::string s;
                                         for (const std::string& f : unplaced) s += f + " ";
                                         return s;
                                     }();
}

TEST(IncludeLayers, NoIncludeRunsUpwardOrSideways) {
    const fs::path root = HG_SOURCE_DIR;
    const std::vector<Include> includes = projectIncludes(root);
    ASSERT_GT(includes.size(), 500u) << "the source tree was not found at " << root;
    std::ostringstream wrong;
    std::map<std::string, std::set<std::string>> graph;
    for (const Include& i : includes) {
        const std::string from = folderOf(i.file), to = folderOf(i.target);
        const auto a = layers().find(from), b = layers().find(to);
        if (a == layers().end() || b == layers().end() || from == to) continue;
        graph[from].insert(to);
        if (b->second >= a->second)
            wrong << i.file << ":" << i.line << ": " << from << " (layer " << a->second << ") includes " << i.target
                  << " (" << to << ", layer " << b->second << ")\n";
    }
    EXPECT_TRUE(wrong.str().empty()) << wrong.str();
    // The graph, for the reader of a failure (and of docs/design.md).
    std::ostringstream g;
    for (const auto& [from, tos] : graph) {
        g << from << " ->";
        for (const std::string& t : tos) g << " " << t;
        g << "\n";
    }
    RecordProperty("include_graph", g.str());
}

// The check itself: a made-up upward include is caught, a downward one not.
TEST(IncludeLayers, TheOrderCatchesAnUpwardInclude) {
    EXPECT_LT(layers().at(folderOf("voxel/volume.h")), layers().at(folderOf("garden/app/garden_session.h")));
    EXPECT_EQ(folderOf("frep/kernels/library/convolution.h"), "frep/kernels");
    EXPECT_LT(layers().at("frep/kernels"), layers().at("frep/language"));
    EXPECT_LT(layers().at("frep/language"), layers().at("frep/compiler"));
    EXPECT_LT(layers().at("frep/compiler"), layers().at("frep/eval"));
    EXPECT_LT(layers().at("frep/eval"), layers().at("voxel"));
    EXPECT_EQ(layers().at("polygonizer/realtime"), layers().at("polygonizer/export")) << "siblings share a layer";
    EXPECT_GT(layers().at("polygonizer/realtime"), layers().at("polygonizer")) << "both sides sit on the shared base";
    EXPECT_EQ(layers().at("garden/session"), layers().at("garden/replay")) << "siblings share a layer";
    EXPECT_GT(layers().at("garden/session"), layers().at("garden/app")) << "a session folder sits above the garden it saves";
}

// One folder talks to OpenGL: garden/render. The desktop, the headset and
// the offscreen replay draw through it, so a change of GL version, state
// or measurement is made in one place. Two exceptions: xr/mock_runtime
// plays a runtime's compositor (it owns the swapchain images), and
// xr/headset.cpp asks GLX for the context the runtime is to share (glX*).
TEST(IncludeLayers, OnlyTheRendererCallsOpenGL) {
    const fs::path root = HG_SOURCE_DIR;
    const std::regex call(R"re((^|[^\w:.>])gl(?!X)[A-Z][a-z]\w*\()re");
    std::ostringstream wrong;
    std::size_t files = 0;
    for (const char* top : {"frep", "io", "jobs", "voxel", "polygonizer", "garden", "xr", "cli"}) {
        for (const auto& entry : fs::recursive_directory_iterator(root / top)) {
            const std::string ext = entry.path().extension().string();
            if (!entry.is_regular_file() || (ext != ".h" && ext != ".cpp")) continue;
            const std::string rel = fs::relative(entry.path(), root).generic_string();
            if (rel.rfind("garden/render/", 0) == 0 || rel.rfind("xr/mock_runtime/", 0) == 0) continue;
            ++files;
            std::ifstream in(entry.path());
            std::string text;
            for (int n = 1; std::getline(in, text); ++n)
                if (std::regex_search(text, call)) wrong << rel << ":" << n << ": " << text << "\n";
        }
    }
    ASSERT_GT(files, 100u) << "the source tree was not found at " << root;
    EXPECT_TRUE(wrong.str().empty()) << "OpenGL called outside garden/render:\n" << wrong.str();
    // The check itself: a call is caught, a method of that name is not.
    EXPECT_TRUE(std::regex_search("    glBindFramebuffer(GL_FRAMEBUFFER, 0);", call));
    EXPECT_FALSE(std::regex_search("GlWindow::glVersionString()", call));
    EXPECT_FALSE(std::regex_search("glXQueryContext(d, c, a, &v);", call));
}

}  // namespace
