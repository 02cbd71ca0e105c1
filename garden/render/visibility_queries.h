// Whole sculptures hidden behind nearer ones are not drawn (issue 25;
// docs/rendering.md, "Hidden sculptures"). After a view's scene pass every
// sculpture's world box that lies wholly in view is drawn against the
// scene's depth inside a GL_ANY_SAMPLES_PASSED query (no colour, no depth
// written). A later frame reads the result without waiting for the GPU:
// a box none of whose samples passed was hidden, and the sculpture's chunks
// are then left out of the scene pass (they still cast the sun's shadow).
//
// A result is trusted only while it can still be true:
//   - the box is grown by kMargin before it is tested, and the result
//     counts only while the eye is within kTrustedMove of where it was
//     tested from (turning the head does not change what hides what: the
//     box was wholly in view, so every ray to it was tested);
//   - the sculpture's box now lies within the box that was tested (one
//     moved, turned, scaled or grown by an edit is drawn until tested
//     again);
//   - nothing in front of it changed: a sculpture moved, edited, remeshed
//     or taken away forgets the results behind it (forgetBehind), tests
//     in flight included, so what it hid is drawn in the very next frame;
//   - it is at most kTrustedFrames old (a bound on anything else);
//   - each view of a frame (a headset's two eyes) keeps its own results.
// So the cost of a wrong guess is bounded; the usual case (a visitor
// standing or walking among sculptures) is exact.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "garden/render/gl_objects.h"
#include "garden/render/shader_program.h"

namespace hg::garden {

class VisibilityQueries {
public:
    static constexpr float kMargin = 0.1f;        // metres the box grows by on every side
    static constexpr float kTrustedMove = 0.05f;  // metres the eye may move from where a box was tested
    static constexpr std::uint64_t kTrustedFrames = 4;

    VisibilityQueries();  // throws GlError naming a shader that fails

    // The next view (`slot`: its place in the frame) from `eye`, in frame `frame`.
    void beginView(int slot, const glm::vec3& eye, std::uint64_t frame);
    // Whether `key`, whose world box is now lo..hi, was hidden when last
    // tested in this view's slot, and that result is still trusted. Reads
    // results that have come in.
    bool hidden(std::uint64_t key, const glm::vec3& lo, const glm::vec3& hi);
    // To test after the scene pass: `key`'s world box lo..hi (grown here by
    // kMargin). Skipped while an earlier test of it is still in flight, or
    // when the grown box is not wholly in front of the view (the caller
    // passes `viewProjection`).
    void test(std::uint64_t key, const glm::vec3& lo, const glm::vec3& hi, const glm::mat4& viewProjection);
    // Draws the view's boxes against the depth of the bound framebuffer
    // (the scene's); returns how many. Leaves colour and depth writes on.
    std::size_t issue(const glm::mat4& viewProjection);
    // Something in the world box lo..hi changed what it covers: every
    // result, in any slot, that it may have hidden is forgotten, and so is
    // every test in flight that it may have hidden (its result is dropped
    // when it comes in). Conservative: the changed box's sphere against the
    // capsule from the tested eye to the tested box's centre, as wide as
    // that box's sphere. Returns how many were forgotten.
    std::size_t forgetBehind(const glm::vec3& lo, const glm::vec3& hi);
    // Forgets every result and test (culling turned off).
    void clear();

private:
    struct Entry {
        gl::Query query;
        bool inFlight = false;
        glm::vec3 flightEye{0.0f}, flightLo{0.0f}, flightHi{0.0f};
        std::uint64_t flightFrame = 0;
        bool flightForgotten = false;  // the scene changed in front of it since it was issued
        bool known = false;  // a result came in
        bool wasHidden = false;
        glm::vec3 testedFrom{0.0f}, testedLo{0.0f}, testedHi{0.0f};  // the eye, the grown box
        std::uint64_t testedFrame = 0;
    };
    struct Box {
        Entry* entry;
        glm::vec3 lo, hi;
    };
    Entry& entry(std::uint64_t key);
    static void collect(Entry& e);

    ShaderProgram program_;
    gl::VertexArray empty_;
    GLint viewProjection_ = -1, lo_ = -1, hi_ = -1;
    std::unordered_map<std::uint64_t, Entry> entries_;  // by slot and key
    std::vector<Box> boxes_;                           // the open view's tests
    int slot_ = 0;
    glm::vec3 eye_{0.0f};
    std::uint64_t frame_ = 0;
};

}  // namespace hg::garden
