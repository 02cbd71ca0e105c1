#include "garden/render/tool_gizmo.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include "garden/app/garden_session.h"
#include "garden/app/sculpture_gizmos.h"
#include "garden/render/shapes.h"
#include "voxel/volume.h"

namespace hg::garden {

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr int kSegments = 64;
constexpr int kTubeRings = 8;      // the torus's tube drawn at this many places round the ring
constexpr float kFaintAlpha = 0.35f;
constexpr int kMirrorGrid = 4;     // cells across the mirror quad

const glm::vec3 kX(1, 0, 0), kY(0, 1, 0), kZ(0, 0, 1);

glm::vec4 faint(glm::vec4 c) { return {c.r, c.g, c.b, kFaintAlpha}; }

// Each loop twice: faint over everything (what is inside the sculpture
// still shows) and opaque with the depth test.
void addSeeThrough(std::vector<GizmoLines>& out, std::vector<glm::vec3> points, const glm::vec4& color,
                   LineMode mode = LineMode::Loop) {
    out.push_back({points, mode, faint(color), true});
    out.push_back({std::move(points), mode, color, false});
}

// Two unit vectors spanning the plane normal to unit `w`.
void planeAxes(const glm::vec3& w, glm::vec3& u, glm::vec3& v) {
    const glm::vec3 helper = std::fabs(w.y) < 0.9f ? kY : kX;
    u = glm::normalize(glm::cross(helper, w));
    v = glm::cross(w, u);
}

// A wire sphere: three great circles and the outline seen from `eye`.
void addSphere(std::vector<GizmoLines>& out, const glm::vec3& c, float r, const glm::vec3& eye, const glm::vec4& color) {
    addSeeThrough(out, circlePoints(c, r, kX, kY, kSegments), color);
    addSeeThrough(out, circlePoints(c, r, kY, kZ, kSegments), color);
    addSeeThrough(out, circlePoints(c, r, kZ, kX, kSegments), color);
    const glm::vec3 toEye = eye - c;
    const float d = glm::length(toEye);
    if (d > r) {
        // The circle where the view cone touches the sphere.
        glm::vec3 u, v;
        const glm::vec3 w = toEye / d;
        planeAxes(w, u, v);
        const float offset = r * r / d;
        addSeeThrough(out, circlePoints(c + offset * w, std::sqrt(r * r - offset * offset), u, v, kSegments), color);
    }
}

// An ellipse about c with semi-axes a along unit u and b along unit v.
std::vector<glm::vec3> ellipse(const glm::vec3& c, const glm::vec3& u, float a, const glm::vec3& v, float b) {
    std::vector<glm::vec3> p;
    for (int k = 0; k < kSegments; ++k) {
        const double t = 2.0 * kPi * k / kSegments;
        p.push_back(c + a * static_cast<float>(std::cos(t)) * u + b * static_cast<float>(std::sin(t)) * v);
    }
    return p;
}

}  // namespace

glm::vec4 toolColor(const ToolSettings& tool) {
    using K = ToolSettings::Kind;
    switch (tool.kind) {
        case K::Carve: return tool.reverse ? glm::vec4(0.3f, 0.9f, 0.35f, 1) : glm::vec4(1.0f, 0.4f, 0.15f, 1);
        case K::Add: return tool.reverse ? glm::vec4(1.0f, 0.4f, 0.15f, 1) : glm::vec4(0.3f, 0.9f, 0.35f, 1);
        case K::Melt: return {0.35f, 0.6f, 1.0f, 1};
        case K::Smooth: return {0.6f, 0.95f, 0.95f, 1};
        case K::Inflate: return tool.reverse ? glm::vec4(0.75f, 0.4f, 1.0f, 1) : glm::vec4(1.0f, 0.75f, 0.4f, 1);
        case K::Perturb: return tool.perturbStrength() > 0 ? glm::vec4(1.0f, 0.9f, 0.2f, 1) : glm::vec4(0.75f, 0.4f, 1.0f, 1);
        case K::Impacts: return {1.0f, 0.3f, 0.8f, 1};
        case K::Move: return {1.0f, 0.9f, 0.3f, 1};
        case K::Sketch: return tool.reverse ? glm::vec4(1.0f, 0.4f, 0.15f, 1) : glm::vec4(0.3f, 0.9f, 0.35f, 1);
        case K::None: break;
    }
    return {1, 1, 1, 1};
}

std::vector<GizmoLines> toolGizmo(const ToolSettings& tool, const glm::vec3& at, const glm::vec3& aimOrigin,
                                  const glm::vec3& aimDirection, const glm::vec3& eye) {
    using K = ToolSettings::Kind;
    std::vector<GizmoLines> out;
    const glm::vec4 color = toolColor(tool);
    switch (tool.kind) {
        case K::Carve:
        case K::Add:
        case K::Melt:
        case K::Smooth:
        case K::Inflate:
            addSphere(out, at, static_cast<float>(tool.radius), eye, color);
            break;
        case K::Perturb: {
            // As applyPerturbation places it: the world's axes, the radii
            // times the scale; a torus's ring in the x-y plane about z.
            const auto r = tool.perturbRadii();
            const float a = static_cast<float>(r[0]), b = static_cast<float>(r[1]), c = static_cast<float>(r[2]);
            if (tool.shape == QuadricShape::Ellipsoid) {
                addSeeThrough(out, ellipse(at, kX, a, kY, b), color);
                addSeeThrough(out, ellipse(at, kY, b, kZ, c), color);
                addSeeThrough(out, ellipse(at, kZ, c, kX, a), color);
            } else {
                const float ring = a, tube = b;
                addSeeThrough(out, circlePoints(at, ring + tube, kX, kY, kSegments), color);
                if (ring > tube) addSeeThrough(out, circlePoints(at, ring - tube, kX, kY, kSegments), color);
                addSeeThrough(out, circlePoints(at + tube * kZ, ring, kX, kY, kSegments), color);
                addSeeThrough(out, circlePoints(at - tube * kZ, ring, kX, kY, kSegments), color);
                for (int k = 0; k < kTubeRings; ++k) {
                    const double t = 2.0 * kPi * k / kTubeRings;
                    const glm::vec3 radial = static_cast<float>(std::cos(t)) * kX + static_cast<float>(std::sin(t)) * kY;
                    addSeeThrough(out, circlePoints(at + ring * radial, tube, radial, kZ, kSegments / 2), color);
                }
            }
            break;
        }
        case K::Impacts: {
            // The spread across the aim where it meets the surface: the
            // disc (uniform), one and two sigmas (gaussian), or the cone's
            // section; the impact's size as a small sphere at its centre.
            glm::vec3 u, v;
            planeAxes(aimDirection, u, v);
            if (tool.spread == ImpactSpread::Cone) {
                const double half = std::min(tool.spreadSize, 89.0) * kPi / 180.0;
                const float rc = glm::length(at - aimOrigin) * static_cast<float>(std::tan(half));
                addSeeThrough(out, circlePoints(at, rc, u, v, kSegments), color);
            } else {
                const float rs = static_cast<float>(tool.spreadSize);
                addSeeThrough(out, circlePoints(at, rs, u, v, kSegments), color);
                if (tool.spread == ImpactSpread::Gaussian)
                    out.push_back({circlePoints(at, 2.0f * rs, u, v, kSegments), LineMode::Loop, faint(color), true});
            }
            addSphere(out, at, static_cast<float>(tool.impactSize), eye, color);
            break;
        }
        case K::None:
        case K::Move:
        case K::Sketch:
            break;
    }
    return out;
}

std::vector<GizmoLines> moveGizmo(const Sculpture& s) {
    std::vector<GizmoLines> out;
    const MoveRing ring = moveRing(s);
    const glm::vec4 color(1.0f, 0.9f, 0.3f, 1.0f);
    // A little above the pivot's height, so the ground does not cover it.
    const glm::vec3 c = ring.centre + glm::vec3(0.0f, 0.02f, 0.0f);
    addSeeThrough(out, circlePoints(c, ring.radius, kX, kZ, kSegments), color);
    // The ring's grab band, and handles across it at the model axes.
    const float inner = ring.radius * (1.0f - kMoveRingGrab), outer = ring.radius * (1.0f + kMoveRingGrab);
    out.push_back({circlePoints(c, inner, kX, kZ, kSegments), LineMode::Loop, faint(color), true});
    out.push_back({circlePoints(c, outer, kX, kZ, kSegments), LineMode::Loop, faint(color), true});
    const glm::vec3 ax = glm::normalize(glm::vec3(s.modelToWorld()[0])), az = glm::normalize(glm::vec3(s.modelToWorld()[2]));
    std::vector<glm::vec3> handles;
    for (const glm::vec3& d : {ax, -ax, az, -az}) {
        handles.push_back(c + inner * d);
        handles.push_back(c + outer * d);
    }
    out.push_back({handles, LineMode::Segments, color, true});
    // The model axes at the pivot: x red, y green, z blue.
    const float len = 0.6f * ring.radius;
    const glm::vec3 ay = glm::normalize(glm::vec3(s.modelToWorld()[1]));
    out.push_back({{c, c + len * ax}, LineMode::Segments, {0.95f, 0.25f, 0.2f, 1}, true});
    out.push_back({{c, c + len * ay}, LineMode::Segments, {0.3f, 0.9f, 0.3f, 1}, true});
    out.push_back({{c, c + len * az}, LineMode::Segments, {0.3f, 0.5f, 1.0f, 1}, true});
    return out;
}

std::vector<GizmoLines> mirrorGizmo(const Sculpture& s) {
    std::vector<GizmoLines> out;
    if (!s.mirror || !s.volume) return out;
    const frep::Box3& b = s.volume->frame.modelBox;
    const glm::vec3 n(static_cast<float>(s.mirror->normal[0]), static_cast<float>(s.mirror->normal[1]),
                      static_cast<float>(s.mirror->normal[2]));
    const glm::vec3 p(static_cast<float>(s.mirror->point[0]), static_cast<float>(s.mirror->point[1]),
                      static_cast<float>(s.mirror->point[2]));
    glm::vec3 u, v;
    planeAxes(glm::normalize(n), u, v);
    // Half the box's extent along u and v (its projection on each axis).
    const glm::vec3 half(static_cast<float>(0.5 * (b.hi[0] - b.lo[0])), static_cast<float>(0.5 * (b.hi[1] - b.lo[1])),
                         static_cast<float>(0.5 * (b.hi[2] - b.lo[2])));
    const float hu = glm::dot(half, glm::abs(u)), hv = glm::dot(half, glm::abs(v));
    const auto world = [&](float su, float sv) {
        return glm::vec3(s.modelToWorld() * glm::vec4(p + su * hu * u + sv * hv * v, 1.0f));
    };
    const glm::vec4 color(0.3f, 0.9f, 0.95f, 1.0f);
    addSeeThrough(out, {world(-1, -1), world(1, -1), world(1, 1), world(-1, 1)}, color);
    std::vector<glm::vec3> grid;
    for (int k = 1; k < kMirrorGrid; ++k) {
        const float t = -1.0f + 2.0f * static_cast<float>(k) / kMirrorGrid;
        grid.insert(grid.end(), {world(t, -1), world(t, 1), world(-1, t), world(1, t)});
    }
    out.push_back({grid, LineMode::Segments, faint(color), true});
    return out;
}

std::vector<GizmoLines> selectionGizmo(const Sculpture& s) {
    std::vector<GizmoLines> out;
    if (!s.volume) return out;
    const frep::Box3& b = s.volume->frame.modelBox;
    const auto corner = [&](int c) {
        const glm::vec4 m(static_cast<float>(c & 1 ? b.hi[0] : b.lo[0]), static_cast<float>(c & 2 ? b.hi[1] : b.lo[1]),
                          static_cast<float>(c & 4 ? b.hi[2] : b.lo[2]), 1.0f);
        return glm::vec3(s.modelToWorld() * m);
    };
    std::vector<glm::vec3> edges;
    for (int c = 0; c < 8; ++c)
        for (const int axis : {1, 2, 4})
            if (!(c & axis)) edges.insert(edges.end(), {corner(c), corner(c | axis)});
    addSeeThrough(out, std::move(edges), glm::vec4(0.95f, 0.95f, 0.95f, 1.0f), LineMode::Segments);
    return out;
}

void drawToolGizmos(Renderer& renderer, const GardenSession& session, const std::optional<Pose>& aim) {
    std::optional<glm::vec3> hit;
    if (aim)
        if (const auto h = session.toolHit(*aim)) hit = h->second;
    drawToolGizmos(renderer, session, aim, hit);
}

void drawToolGizmos(Renderer& renderer, const GardenSession& session, const std::optional<Pose>& aim,
                    const std::optional<glm::vec3>& hit) {
    std::vector<GizmoLines> lines;
    const int selected = session.selected();
    const ToolSettings& tool = session.tool();
    if (selected >= 0) {
        const Sculpture& s = session.sculptures()[static_cast<std::size_t>(selected)];
        for (GizmoLines& l : mirrorGizmo(s)) lines.push_back(std::move(l));
        if (tool.kind == ToolSettings::Kind::Move)
            for (GizmoLines& l : moveGizmo(s)) lines.push_back(std::move(l));
        else
            for (GizmoLines& l : selectionGizmo(s)) lines.push_back(std::move(l));
    }
    if (aim && hit && tool.kind != ToolSettings::Kind::None && tool.kind != ToolSettings::Kind::Move)
        for (GizmoLines& l : toolGizmo(tool, *hit, aim->position, aim->forward(), session.navigator().eye()))
            lines.push_back(std::move(l));
    // The outline being sketched, as drawn so far; the gesture as drawn.
    if (session.sketchPath().size() >= 2) addSeeThrough(lines, session.sketchPath(), toolColor(tool), LineMode::Strip);
    if (session.gestureTrail().size() >= 2)
        lines.push_back({session.gestureTrail(), LineMode::Strip, glm::vec4(0.6f, 0.85f, 1.0f, 1.0f), true});
    // Deformable models as wireframes (the active one brighter): each
    // triangle's edges once, in the garden's frame.
    for (const GardenSession::ModelView& m : session.models()) {
        if (m.sculpture < 0 || !session.sculptures()[static_cast<std::size_t>(m.sculpture)].onShow()) continue;
        const glm::mat4 toWorld = session.sculptures()[static_cast<std::size_t>(m.sculpture)].modelToWorld();
        std::vector<glm::vec3> segments;
        segments.reserve(m.triangles->size() * 6);
        const auto at = [&](std::uint32_t v) { return glm::vec3(toWorld * glm::vec4(glm::vec3((*m.vertices)[v]), 1.0f)); };
        for (const auto& t : *m.triangles)
            for (int e = 0; e < 3; ++e)
                if (t[static_cast<std::size_t>(e)] < t[static_cast<std::size_t>((e + 1) % 3)]) {
                    segments.push_back(at(t[static_cast<std::size_t>(e)]));
                    segments.push_back(at(t[static_cast<std::size_t>((e + 1) % 3)]));
                }
        const bool active = m.name == session.activeModel();
        addSeeThrough(lines, std::move(segments), active ? glm::vec4(0.3f, 0.9f, 1.0f, 1.0f) : glm::vec4(0.3f, 0.6f, 0.7f, 0.8f),
                      LineMode::Segments);
    }
    // Depth-tested lines first, then what shows over everything.
    for (const GizmoLines& l : lines)
        if (!l.overEverything) renderer.drawLines(l.points, l.color, l.mode, true);
    for (const GizmoLines& l : lines)
        if (l.overEverything) renderer.drawLines(l.points, l.color, l.mode, false);
}

}  // namespace hg::garden
