#include "garden/window/garden_view.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "garden/render/frustum_test.h"
#include "garden/render/garden_ground.h"
#include "garden/window/impostor_identity.h"
#include "garden/window/path_mesh.h"
#include "garden/window/view_lights.h"
#include "garden/render/material_look.h"
#include "garden/scene/to_glm.h"

namespace hg::garden {

namespace {

// A marker for a missing sculpture: a red wire cube of 1 m at its place.
std::vector<glm::vec3> cubeEdges(const glm::mat4& place, float scaleToMetre) {
    std::vector<glm::vec3> p;
    const float h = 0.5f / scaleToMetre;
    auto corner = [&](int i) {
        return glm::vec3(place * glm::vec4((i & 1 ? h : -h), (i & 2 ? 2 * h : 0.0f), (i & 4 ? h : -h), 1.0f));
    };
    for (int i = 0; i < 8; ++i)
        for (int b = 0; b < 3; ++b) {
            const int j = i | (1 << b);
            if (j != i) {
                p.push_back(corner(i));
                p.push_back(corner(j));
            }
        }
    return p;
}

// Milliseconds since `start`: the upload stage keeps to its allowance.
double msSince(const std::chrono::steady_clock::time_point& start) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

// The world box around a model box placed by `model`.
void worldBox(const glm::mat4& model, const glm::vec3& lo, const glm::vec3& hi, glm::vec3& worldLo, glm::vec3& worldHi) {
    worldLo = glm::vec3(1e30f);
    worldHi = glm::vec3(-1e30f);
    for (int c = 0; c < 8; ++c) {
        const glm::vec3 p(model * glm::vec4(c & 1 ? hi.x : lo.x, c & 2 ? hi.y : lo.y, c & 4 ? hi.z : lo.z, 1.0f));
        worldLo = glm::min(worldLo, p);
        worldHi = glm::max(worldHi, p);
    }
}

}  // namespace

ViewDraw viewDrawOf(const RenderStats& r) {
    ViewDraw d{r.trianglesDrawn,  r.chunksDrawn,      r.drawCalls,       r.gpuMs(),         {},
               r.impostorsDrawn,  r.sculpturesHidden, r.shadowMapsDrawn, r.shadowMapsKept};
    d.gpuPassMs = GpuPassMs{r.gpuShadowMs, r.gpuSceneMs, r.gpuOcclusionMs, r.gpuPostMs};
    d.picturesKept = r.picturesKept;
    d.picturesSharpened = r.picturesSharpened;
    return d;
}

ViewUpload GardenView::upload(const GardenSession& session, double allowanceMs) {
    const auto start = std::chrono::steady_clock::now();
    ViewUpload done;
    std::size_t& bytes = done.bytes;
    bool spent = false;
    const Garden& g = session.garden();
    for (std::size_t p = 0; p < g.paths.size(); ++p)
        if (!renderer_.has(pathId(p))) bytes += renderer_.upload(pathId(p), 1, pathMesh(g.paths[p], g.ground.height));
    for (std::size_t s = 0; s < session.sculptures().size(); ++s) {
        const Sculpture& st = session.sculptures()[s];
        if (!st.onShow()) continue;
        const poly::RemeshQueue& q = *st.queue;
        if (uploaded_.size() <= s) uploaded_.resize(s + 1, 0);
        if (frames_.size() <= s) frames_.resize(s + 1);
        if (frames_[s].frameGeneration != st.frameGeneration) {
            for (std::size_t c = 0; c < frames_[s].chunks; ++c) renderer_.drop(chunkId(s, c));
            frames_[s].frameGeneration = st.frameGeneration;
            uploaded_[s] = 0;
        }
        frames_[s].chunks = std::max(frames_[s].chunks, q.count());
        if (uploaded_[s] == q.shownGeneration() + 1) continue;  // nothing new on show
        if (spent) {
            ++done.pending;
            continue;
        }
        for (std::size_t c = 0; c < q.count(); ++c)
            if (const auto m = q.mesh(c)) bytes += renderer_.upload(chunkId(s, c), q.version(c), *m);
        uploaded_[s] = q.shownGeneration() + 1;
        // The box around what is on show, for the visibility test: the
        // layout's box holds empty chunks and the band around the surface.
        Uploaded& u = frames_[s];
        u.meshLo = glm::vec3(1e30f);
        u.meshHi = glm::vec3(-1e30f);
        for (std::size_t c = 0; c < q.count(); ++c) {
            glm::vec3 lo, hi;
            if (!renderer_.bounds(chunkId(s, c), lo, hi)) continue;
            u.meshLo = glm::min(u.meshLo, lo);
            u.meshHi = glm::max(u.meshHi, hi);
        }
        spent = msSince(start) >= allowanceMs;
    }
    if (!spent) bakeImpostors(session, start, allowanceMs);
    if (msSince(start) < allowanceMs)
        renderer_.compactArena(arenaCompactBytes_);
    return done;
}

bool GardenView::drawnAsCard(const GardenSession& session, std::size_t s, const RenderMaterial& m,
                             const double lo[3], const double hi[3], const glm::vec3& eye) {
    if (far_.size() <= s) far_.resize(s + 1);
    Far& f = far_[s];
    f.wanted = false;
    const float distance = impostorDistance_;
    if (!(distance > 0.0f) || m.edges != 0) return f.card = false;
    const Sculpture& st = session.sculptures()[s];
    const glm::vec3 a(static_cast<float>(lo[0]), static_cast<float>(lo[1]), static_cast<float>(lo[2]));
    const glm::vec3 b(static_cast<float>(hi[0]), static_cast<float>(hi[1]), static_cast<float>(hi[2]));
    const glm::vec3 centre = glm::vec3(st.modelToWorld() * glm::vec4(0.5f * (a + b), 1.0f));
    const float radius = 0.5f * glm::length(b - a) * static_cast<float>(st.scale());
    const float away = glm::length(eye - centre) - radius;
    // A little nearer to go back to the chunks than to leave them: no
    // flicker for a visitor standing at the distance.
    if (away <= (f.card ? 0.9f : 1.0f) * distance) return f.card = false;
    const ImpostorId id = impostorId(session, s, m);
    if (renderer_.drawImpostor(id.key, id.version, st.modelToWorld(), m)) return f.card = true;
    f.wanted = true;
    f.away = away;
    return f.card = false;
}

std::size_t GardenView::impostorsWanted() const {
    return static_cast<std::size_t>(std::count_if(far_.begin(), far_.end(), [](const Far& f) { return f.wanted; }));
}

void GardenView::forgetHiddenBehindChanges(const GardenSession& session) {
    const auto& sculptures = session.sculptures();
    if (frames_.size() < sculptures.size()) frames_.resize(sculptures.size());
    for (std::size_t s = 0; s < sculptures.size(); ++s) {
        const Sculpture& st = sculptures[s];
        Uploaded& u = frames_[s];
        Uploaded::Cover now;
        now.shown = st.onShow() && (only_ < 0 || s == static_cast<std::size_t>(only_));
        if (now.shown) {
            now.card = s < far_.size() && far_[s].card;
            now.model = st.modelToWorld();
            now.meshes = s < uploaded_.size() ? uploaded_[s] : 0;
            if (u.meshLo.x <= u.meshHi.x) worldBox(now.model, u.meshLo, u.meshHi, now.lo, now.hi);
        }
        if (!now.sameAs(u.cover))
            for (const Uploaded::Cover* c : {&u.cover, &now})
                if (c->shown && c->lo.x <= c->hi.x) renderer_.forgetHiddenBehind(c->lo, c->hi);
        u.cover = now;
    }
}

RenderMaterial GardenView::materialOf(const Sculpture& st) const {
    const frep::Box3& box = st.layout->frame().modelBox;
    const double size = std::max({box.hi[0] - box.lo[0], box.hi[1] - box.lo[1], box.hi[2] - box.lo[2]});
    return lookedAt(renderMaterial(st.material, detailScaleFor(size)), look_);
}

void GardenView::bakeImpostors(const GardenSession& session, const std::chrono::steady_clock::time_point& start,
                               double allowanceMs) {
    std::vector<std::size_t> wanted;
    for (std::size_t s = 0; s < far_.size() && s < session.sculptures().size(); ++s)
        if (far_[s].wanted) wanted.push_back(s);
    std::sort(wanted.begin(), wanted.end(), [&](std::size_t a, std::size_t b) { return far_[a].away < far_[b].away; });
    int baked = 0;
    std::vector<ChunkId> ids;
    for (std::size_t s : wanted) {
        if (baked >= kBakesPerFrame ||
            msSince(start) >= allowanceMs)
            break;
        const Sculpture& st = session.sculptures()[s];
        // From the meshes on show, whole: every chunk meshed at its level and uploaded.
        if (!st.onShow() || st.queue->pending() != 0 || st.queue->meshing() || s >= uploaded_.size() ||
            uploaded_[s] != st.queue->shownGeneration() + 1)
            continue;
        const RenderMaterial m = materialOf(st);
        const ImpostorId id = impostorId(session, s, m);
        far_[s].wanted = false;
        if (renderer_.hasImpostor(id.key, id.version)) continue;  // a copy's bake, this frame
        ids.clear();
        for (std::size_t c = 0; c < st.queue->count(); ++c) ids.push_back(chunkId(s, c));
        if (renderer_.bakeImpostor(id.key, id.version, ids, m)) ++baked;
    }
}

void GardenView::render(const GardenSession& session, glm::ivec2 viewport, float fovY) {
    render(session, viewport, session.navigator().view(),
           gardenProjection(fovY, viewport),
           session.navigator().eye());
}

void GardenView::render(const GardenSession& session, glm::ivec2 viewport, const glm::mat4& view,
                        const glm::mat4& projection, const glm::vec3& eye) {
    const Garden& g = session.garden();
    View v;
    v.view = view;
    v.projection = projection;
    v.eye = eye;
    v.viewport = viewport;
    addGardenLights(g, v);
    v.hazeDistance = kGardenHazeDistance;
    v.clouds = kGardenClouds;
    renderer_.beginFrame(v);

    // The garden's lawn, mown in stripes, a meadow beyond it to the far
    // plane, where the haze meets the sky (garden/render/garden_ground.h).
    const GroundStyle ground =
        gardenGround(glm::vec3(g.ground.material.color[0], g.ground.material.color[1], g.ground.material.color[2]),
                     glm::vec2(static_cast<float>(g.ground.size[0]), static_cast<float>(g.ground.size[1])));
    renderer_.drawGround(ground);

    for (std::size_t p = 0; p < g.paths.size(); ++p)
        renderer_.drawChunk(pathId(p), glm::mat4(1.0f), renderMaterial(g.paths[p].material, kPathDetailScale));
    if (renderer_.occlusionCulling()) forgetHiddenBehindChanges(session);
    const auto& sculptures = session.sculptures();
    for (std::size_t s = 0; s < sculptures.size(); ++s) {
        const Sculpture& st = sculptures[s];
        if (st.removed || (only_ >= 0 && s != static_cast<std::size_t>(only_))) continue;
        if (st.missing()) {
            renderer_.drawLines(cubeEdges(st.modelToWorld(), static_cast<float>(st.scale())), glm::vec4(0.9f, 0.1f, 0.1f, 1.0f),
                                LineMode::Segments);
            continue;
        }
        if (!st.hasGrid()) continue;  // still loading
        const RenderMaterial m = materialOf(st);
        const glm::mat4 mvp = v.projection * v.view * st.modelToWorld();
        // The sculpture's whole box first (the layout's first and last
        // chunks hold its corners): one test instead of one per chunk for a
        // sculpture wholly in view or wholly out of it.
        const std::size_t chunks = st.queue->count();
        if (chunks == 0) continue;
        double lo[3], hi[3], last[3];
        st.layout->modelBox(0, lo, last);
        st.layout->modelBox(chunks - 1, last, hi);
        const InView whole = frustumTest(mvp, toGlm(lo), toGlm(hi));
        if (whole == InView::Outside) continue;
        if (drawnAsCard(session, s, m, lo, hi, eye)) continue;
        // Hidden behind nearer sculptures when last tested: its chunks only
        // cast their shadow (docs/rendering.md, "Hidden sculptures").
        bool seen = true;
        if (renderer_.occlusionCulling() && s < frames_.size() && frames_[s].meshLo.x <= frames_[s].meshHi.x) {
            glm::vec3 worldLo, worldHi;
            worldBox(st.modelToWorld(), frames_[s].meshLo, frames_[s].meshHi, worldLo, worldHi);
            seen = !renderer_.wasHidden(s, worldLo, worldHi);
            renderer_.testVisibility(s, worldLo, worldHi);
        }
        for (std::size_t c = 0; c < chunks; ++c) {
            const auto mesh = st.queue->mesh(c);
            if (!mesh || mesh->empty()) continue;
            if (whole == InView::Partly) {
                st.layout->modelBox(c, lo, hi);
                if (frustumTest(mvp, toGlm(lo), toGlm(hi)) == InView::Outside) continue;
            }
            renderer_.drawChunk(chunkId(s, c), st.modelToWorld(), m, seen);
        }
    }
    if (only_ >= 0) return;  // one sculpture on show: no markers on the ground
    // Every morph's triangle; the active one's brighter, with its selector.
    for (int r : session.morphResults()) {
        const auto t = session.morphTriangle(r);
        const bool active = r == session.activeMorph();
        std::vector<glm::vec3> loop;
        for (const auto& c : t->corners) loop.emplace_back(static_cast<float>(c[0]), 0.02f, static_cast<float>(c[1]));
        renderer_.drawLines(loop, active ? glm::vec4(0.95f, 0.85f, 0.2f, 1.0f) : glm::vec4(0.6f, 0.55f, 0.25f, 1.0f),
                            LineMode::Loop);
        if (const auto& w = session.morphWeights(r)) {
            const glm::vec3 p(static_cast<float>(w->point[0]), 0.02f, static_cast<float>(w->point[1]));
            renderer_.drawLines({p - glm::vec3(0.15f, 0, 0), p + glm::vec3(0.15f, 0, 0), p - glm::vec3(0, 0, 0.15f),
                                 p + glm::vec3(0, 0, 0.15f)},
                                active ? glm::vec4(0.95f, 0.3f, 0.1f, 1.0f) : glm::vec4(0.6f, 0.35f, 0.2f, 1.0f),
                                LineMode::Segments);
        }
    }
    if (const auto& d = session.detail())
        renderer_.drawSphere(toGlm(d->center), static_cast<float>(d->radius), glm::vec4(0.2f, 0.85f, 0.3f, 1.0f), true);
}

}  // namespace hg::garden
