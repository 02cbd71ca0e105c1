// `hypergarden turntable` as a user runs it, under Xvfb: PNG frames of the
// size asked, the sculpture in the middle of each, the camera going round
// it (frame k of N is the view at k/N of a turn), a session's sculpture
// shown with its edits, and clear errors that write no frame.
#include <stb/stb_image.h>

#include <cmath>
#include <cstdlib>
#include <fstream>

#include "../cli_fixture.h"
#include "../garden/session_garden.h"
#include "garden/session/open_session.h"

namespace hg::garden {
namespace {

struct Image {
    int width = 0, height = 0;
    std::vector<unsigned char> rgba;
    explicit operator bool() const { return !rgba.empty(); }
    const unsigned char* at(int x, int y) const { return &rgba[(static_cast<std::size_t>(y) * width + x) * 4]; }
};

Image load(const std::filesystem::path& path) {
    Image im;
    int channels = 0;
    if (unsigned char* px = stbi_load(path.c_str(), &im.width, &im.height, &channels, 4)) {
        im.rgba.assign(px, px + static_cast<std::size_t>(im.width) * im.height * 4);
        stbi_image_free(px);
    }
    return im;
}

// The middle third of the image (both ways).
template <class F>
void middle(const Image& im, F f) {
    for (int y = im.height / 3; y < 2 * im.height / 3; ++y)
        for (int x = im.width / 3; x < 2 * im.width / 3; ++x) f(x, y);
}

// Mean absolute difference per channel over the middle third, 0..255.
double middleDifference(const Image& a, const Image& b) {
    double sum = 0.0;
    int n = 0;
    middle(a, [&](int x, int y) {
        for (int c = 0; c < 3; ++c) sum += std::abs(int(a.at(x, y)[c]) - int(b.at(x, y)[c]));
        n += 3;
    });
    return sum / n;
}

// Pixels whose colour differs clearly between two images.
int differingPixels(const Image& a, const Image& b) {
    int n = 0;
    for (int y = 0; y < a.height; ++y)
        for (int x = 0; x < a.width; ++x) {
            int d = 0;
            for (int c = 0; c < 3; ++c) d += std::abs(int(a.at(x, y)[c]) - int(b.at(x, y)[c]));
            n += d > 30;
        }
    return n;
}

// The share of the middle third that is the small garden's red material.
double redShare(const Image& im) {
    int red = 0, n = 0;
    middle(im, [&](int x, int y) {
        const unsigned char* p = im.at(x, y);
        red += p[0] > 60 && p[0] > 2 * p[1] && p[0] > 2 * p[2];
        ++n;
    });
    return static_cast<double>(red) / n;
}

class TurntableCli : public ::hg::test::CliTest {
protected:
    void SetUp() override {
        CliTest::SetUp();
        if (IsSkipped()) return;
        const char* d = std::getenv("DISPLAY");
        if (!d || !*d) GTEST_SKIP() << "no X display: run under xvfb-run -a";
        gardenFile = test::writeSmallGarden(dir / "g");
    }
    ::hg::test::CommandRun turntable(const std::string& input, const std::string& out, const std::string& more) {
        return ::hg::test::runHypergarden("turntable " + input + " --sculpture a -o " + path(out) + " " + more);
    }
    // Ball `a` of the small garden in a session, a groove carved down the
    // side that faces where the visitor starts (+z, a little +x): frame 0
    // looks at it. Clear of the ball's extremes, so the framing (to the
    // shown surface's box) is the unedited ball's.
    void carveSession() {
        SessionSettings settings;
        settings.maxLevel = 0;
        OpenedSession o = openSession({(dir / "session").string(), gardenFile}, settings);
        ASSERT_EQ(o.error, "");
        const int a = o.session->findSculpture("a");
        ASSERT_EQ(o.session->applyStroke(a, StrokeTool::Carve, {{0.33, 0.4, -1.98}, {0.33, 0.6, -1.98}}, 0.1), "");
    }
    std::string gardenFile;
};

TEST_F(TurntableCli, FramesOfTheSizeAskedShowTheSculptureGoingRound) {
    const auto r = turntable("'" + gardenFile + "'", "four", "--frames 4 --size 96x72");
    ASSERT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("wrote 4 frames of 'a'"), std::string::npos) << r.output;
    EXPECT_FALSE(exists("four/a-0004.png")) << "frame N is frame 0 again: not written";
    std::vector<Image> frames;
    for (int f = 0; f < 4; ++f) {
        char name[32];
        std::snprintf(name, sizeof name, "four/a-%04d.png", f);
        frames.push_back(load(dir / name));
        ASSERT_TRUE(frames.back()) << name << " is a PNG";
        EXPECT_EQ(frames.back().width, 96) << name;
        EXPECT_EQ(frames.back().height, 72) << name;
        // Framed to its surface: the red ball fills much of the middle.
        EXPECT_GT(redShare(frames.back()), 0.4) << name;
    }
    // The camera goes round: the garden behind the ball (the ground's
    // grid, the sun's side of the ball) changes from frame to frame.
    for (int f = 0; f < 4; ++f) EXPECT_GT(middleDifference(frames[f], frames[(f + 1) % 4]), 2.0) << f;
    // Frame k of N is the view at k/N of a turn: half a turn in two frames
    // is frame 2 of four.
    const auto two = turntable("'" + gardenFile + "'", "two", "--frames 2 --size 96x72");
    ASSERT_EQ(two.status, 0) << two.output;
    const Image half = load(dir / "two" / "a-0001.png");
    ASSERT_TRUE(half);
    EXPECT_LT(middleDifference(half, frames[2]), 0.5);
    EXPECT_GT(middleDifference(half, frames[1]), 2.0);
}

TEST_F(TurntableCli, ASessionShowsTheSculptureWithItsEdits) {
    carveSession();
    const auto listing = [&] {
        std::string names;
        for (const auto& e : std::filesystem::recursive_directory_iterator(dir / "session"))
            names += e.path().string() + " " +
                     (e.is_regular_file() ? std::to_string(std::filesystem::file_size(e.path())) : "") + "\n";
        return names;
    };
    const std::string before = listing();
    const auto carved = turntable(path("session"), "carved", "--frames 2 --size 96x96 --quality low");
    ASSERT_EQ(carved.status, 0) << carved.output;
    const auto plain = turntable("'" + gardenFile + "'", "plain", "--frames 2 --size 96x96 --quality low");
    ASSERT_EQ(plain.status, 0) << plain.output;
    const Image carvedFront = load(dir / "carved" / "a-0000.png"), plainFront = load(dir / "plain" / "a-0000.png");
    const Image carvedBack = load(dir / "carved" / "a-0001.png"), plainBack = load(dir / "plain" / "a-0001.png");
    ASSERT_TRUE(carvedFront && plainFront && carvedBack && plainBack);
    // The groove faces the first frame and is hidden behind the ball in the
    // second (the back of the ball is the garden file's).
    const int front = differingPixels(carvedFront, plainFront), back = differingPixels(carvedBack, plainBack);
    EXPECT_GT(front, 20);
    EXPECT_LT(back * 10, front) << "front " << front << ", back " << back;
    // Read only: the session folder is as it was.
    EXPECT_EQ(listing(), before);
}

TEST_F(TurntableCli, BadInputGivesAClearMessageAndNoFrame) {
    struct Case {
        std::string args, message;
    };
    const std::string g = "'" + gardenFile + "'";
    std::ofstream(dir / "file.png") << "x";
    const Case cases[] = {
        {"turntable " + g + " --sculpture metamorfosis -o " + path("out"), "did you mean 'metamorphosis'"},
        {"turntable " + g + " --sculpture nobody -o " + path("out"), "its sculptures: 'a' 'b' 'c' 'lost' 'metamorphosis'"},
        {"turntable " + g + " --sculpture lost -o " + path("out"), "sculpture 'lost' is missing"},
        {"turntable " + g + " --sculpture a --size 96by72 -o " + path("out"), "--size '96by72': expected WIDTHxHEIGHT"},
        {"turntable " + g + " --sculpture a --size 8x8 -o " + path("out"), "each 16 to 8192 pixels"},
        {"turntable " + g + " --sculpture a -o " + path("file.png"), "not a folder"},
        {"turntable " + path("none.json") + " --sculpture a -o " + path("out"), "no such session folder or garden file"},
    };
    for (const Case& c : cases) {
        const auto r = ::hg::test::runHypergarden(c.args);
        EXPECT_NE(r.status, 0) << c.args;
        EXPECT_NE(r.output.find(c.message), std::string::npos) << c.args << "\n" << r.output;
        EXPECT_FALSE(exists("out/a-0000.png")) << c.args;
    }
}

}  // namespace
}  // namespace hg::garden
