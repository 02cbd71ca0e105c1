#include "garden/render/visibility_queries.h"

#include "garden/render/frustum_test.h"

#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/vec4.hpp>

namespace hg::garden {
namespace {

// A box's 12 triangles from gl_VertexID alone (corner bits x, y, z).
const char* const kBoxVertex = R"(#version 330 core
uniform mat4 uViewProjection;
uniform vec3 uLo, uHi;
const int kCorner[36] = int[36](0, 1, 3, 0, 3, 2,  4, 6, 7, 4, 7, 5,  0, 4, 5, 0, 5, 1,
                                2, 3, 7, 2, 7, 6,  0, 2, 6, 0, 6, 4,  1, 5, 7, 1, 7, 3);
void main() {
    int c = kCorner[gl_VertexID];
    vec3 p = mix(uLo, uHi, vec3(float(c & 1), float((c >> 1) & 1), float((c >> 2) & 1)));
    gl_Position = uViewProjection * vec4(p, 1.0);
}
)";
const char* const kBoxFragment = R"(#version 330 core
void main() {}
)";

}  // namespace

VisibilityQueries::VisibilityQueries()
    : program_("visibility boxes", kBoxVertex, kBoxFragment),
      empty_(gl::VertexArray::create()),
      viewProjection_(program_.uniform("uViewProjection")),
      lo_(program_.uniform("uLo")),
      hi_(program_.uniform("uHi")) {}

void VisibilityQueries::beginView(int slot, const glm::vec3& eye, std::uint64_t frame) {
    slot_ = slot;
    eye_ = eye;
    frame_ = frame;
    boxes_.clear();
}

VisibilityQueries::Entry& VisibilityQueries::entry(std::uint64_t key) {
    // A sculpture's index fills the low 48 bits; the view's slot the rest.
    return entries_[(static_cast<std::uint64_t>(slot_) << 48) ^ key];
}

void VisibilityQueries::collect(Entry& e) {
    if (!e.inFlight) return;
    GLuint available = 0;
    glGetQueryObjectuiv(e.query.get(), GL_QUERY_RESULT_AVAILABLE, &available);
    if (!available) return;
    GLuint passed = 0;
    glGetQueryObjectuiv(e.query.get(), GL_QUERY_RESULT, &passed);
    e.inFlight = false;
    if (e.flightForgotten) return;  // tested against a scene that has since changed in front of it
    e.known = true;
    e.wasHidden = passed == 0;
    e.testedFrom = e.flightEye;
    e.testedLo = e.flightLo;
    e.testedHi = e.flightHi;
    e.testedFrame = e.flightFrame;
}

bool VisibilityQueries::hidden(std::uint64_t key, const glm::vec3& lo, const glm::vec3& hi) {
    auto found = entries_.find((static_cast<std::uint64_t>(slot_) << 48) ^ key);
    if (found == entries_.end()) return false;
    Entry& e = found->second;
    collect(e);
    const bool within = glm::all(glm::greaterThanEqual(lo, e.testedLo)) && glm::all(glm::lessThanEqual(hi, e.testedHi));
    return e.known && e.wasHidden && within && frame_ - e.testedFrame <= kTrustedFrames &&
           glm::distance(eye_, e.testedFrom) <= kTrustedMove;
}

void VisibilityQueries::test(std::uint64_t key, const glm::vec3& lo, const glm::vec3& hi,
                             const glm::mat4& viewProjection) {
    const glm::vec3 grownLo = lo - glm::vec3(kMargin), grownHi = hi + glm::vec3(kMargin);
    // Every ray that could meet the box is in the picture, so a box none of
    // whose pixels passed the depth test hides nothing that another turn of
    // the head (from the same point) would show.
    if (frustumTest(viewProjection, grownLo, grownHi) != InView::Wholly) return;
    Entry& e = entry(key);
    collect(e);
    if (e.inFlight) return;
    boxes_.push_back({&e, grownLo, grownHi});
}

std::size_t VisibilityQueries::issue(const glm::mat4& viewProjection) {
    if (boxes_.empty()) return 0;
    program_.use();
    glUniformMatrix4fv(viewProjection_, 1, GL_FALSE, glm::value_ptr(viewProjection));
    glBindVertexArray(empty_.get());
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    glDepthMask(GL_FALSE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDisable(GL_CULL_FACE);  // the far faces count too: the box is a volume
    for (const Box& b : boxes_) {
        Entry& e = *b.entry;
        if (!e.query) e.query = gl::Query::create();
        glUniform3fv(lo_, 1, glm::value_ptr(b.lo));
        glUniform3fv(hi_, 1, glm::value_ptr(b.hi));
        glBeginQuery(GL_ANY_SAMPLES_PASSED, e.query.get());
        glDrawArrays(GL_TRIANGLES, 0, 36);
        glEndQuery(GL_ANY_SAMPLES_PASSED);
        e.inFlight = true;
        e.flightEye = eye_;
        e.flightLo = b.lo;
        e.flightHi = b.hi;
        e.flightFrame = frame_;
        e.flightForgotten = false;
    }
    glEnable(GL_CULL_FACE);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glBindVertexArray(0);
    const std::size_t issued = boxes_.size();
    boxes_.clear();
    return issued;
}

namespace {

// Whether the sphere (c, r) may stand between `eye` and the box lo..hi:
// it meets the capsule around the segment from the eye to the box's centre
// whose radius is the box's bounding sphere's (which holds every ray from
// the eye to the box).
bool mayStandBetween(const glm::vec3& c, float r, const glm::vec3& eye, const glm::vec3& lo, const glm::vec3& hi) {
    const glm::vec3 centre = 0.5f * (lo + hi);
    const float boxRadius = 0.5f * glm::length(hi - lo);
    const glm::vec3 axis = centre - eye;
    const float lengthSq = glm::dot(axis, axis);
    const float t = lengthSq > 0.0f ? glm::clamp(glm::dot(c - eye, axis) / lengthSq, 0.0f, 1.0f) : 0.0f;
    return glm::distance(c, eye + t * axis) <= r + boxRadius;
}

}  // namespace

std::size_t VisibilityQueries::forgetBehind(const glm::vec3& lo, const glm::vec3& hi) {
    const glm::vec3 c = 0.5f * (lo + hi);
    const float r = 0.5f * glm::length(hi - lo);
    std::size_t forgotten = 0;
    for (auto& [key, e] : entries_) {
        if (e.known && e.wasHidden && mayStandBetween(c, r, e.testedFrom, e.testedLo, e.testedHi)) {
            e.known = false;
            ++forgotten;
        }
        if (e.inFlight && !e.flightForgotten && mayStandBetween(c, r, e.flightEye, e.flightLo, e.flightHi)) {
            e.flightForgotten = true;
            ++forgotten;
        }
    }
    return forgotten;
}

void VisibilityQueries::clear() {
    entries_.clear();
    boxes_.clear();
}

}  // namespace hg::garden
