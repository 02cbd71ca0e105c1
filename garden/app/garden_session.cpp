#include "garden/app/garden_session.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>

#include "garden/gesture/gesture_recognizer.h"
#include "garden/app/grid_pager.h"
#include "garden/app/sculpture_loader.h"
#include "garden/app/sculpture_sampling.h"
#include "garden/morph/garden_morph.h"
#include "garden/morph/morph_blend.h"
#include "garden/morph/morph_sources.h"
#include "garden/morph/morph_state.h"
#include "garden/sculpt/sculpture_edits.h"
#include "garden/scene/to_glm.h"
#include "jobs/job_thread.h"
#include "polygonizer/realtime/meshing_worker.h"
#include "voxel/sampler.h"

namespace hg::garden {

namespace {

constexpr int kLevelRefreshFrames = 45;
// A sculpture whose chunks take different levels is selected chunk by
// chunk again only once the eye has moved this fraction of its distance
// to the sculpture (or its errors, the detail sphere, its grid's residence
// or the camera's pixels changed): levels change at distances, so a level is at most
// this fraction late, and a walk past hundreds of such sculptures costs a
// test per sculpture a frame, not one per chunk.
constexpr double kReselectMove = 0.01;
// Chunk errors an edit or a blend left to be measured again, on a grid in
// memory (the only kind ChunkErrors::refresh can measure).
bool errorsWaiting(const Sculpture& s) { return s.errors && s.errors->unknown() > 0 && s.volume->resident(); }
// A far grid is read back from disk once the viewer is within this factor
// of the distance where its chunks take level 0, and may go again only
// beyond the larger one (so a visitor at the edge does not make it come and
// go).
constexpr double kBringBackMargin = 1.5;
constexpr double kLetGoMargin = 2.0;

// From a model point to the nearest point of the chunks' bound (0 inside).
double distanceToBound(const poly::ChunkLayout& layout, const std::array<double, 3>& p) {
    double lo[3], hi[3];
    layout.modelBounds(lo, hi);
    double d2 = 0.0;
    for (int a = 0; a < 3; ++a) {
        const double d = std::max({lo[a] - p[a], 0.0, p[a] - hi[a]});
        d2 += d * d;
    }
    return std::sqrt(d2);
}
// How near its triangle (metres on the ground) a drag of the selector must begin.
constexpr double kMorphPickReach = 0.25;

// The morph result a reader means: `sculpture`, or the active one for -1;
// null when that is no morph result.
const Sculpture* morphResultAt(const std::vector<Sculpture>& all, int sculpture, int active) {
    if (sculpture < 0) sculpture = active;
    if (sculpture < 0 || sculpture >= static_cast<int>(all.size())) return nullptr;
    const Sculpture& s = all[static_cast<std::size_t>(sculpture)];
    return s.morphResult() ? &s : nullptr;
}

// The frame's upload limit: what this frame may still show. A group larger
// than the whole limit is shown alone, in a frame that has shown nothing.
void limitShownBytes(poly::RemeshBudget& budget, std::size_t byteLimit, const FrameStats& st) {
    if (byteLimit == 0) return;
    budget.showBytes = byteLimit - std::min(byteLimit, st.meshBytesShown);
    budget.oversized = st.groupsShown == 0;
}

void addRemeshReport(FrameStats& st, const poly::RemeshReport& r) {
    st.chunksMeshed += r.meshed;
    st.chunksShown += r.shown;
    st.meshBytesShown += r.bytesShown;
    st.groupsShown += r.groupsShown;
}

}  // namespace

glm::mat4 placementMatrix(const Placement& p) {
    glm::mat4 m = glm::translate(glm::mat4(1.0f), toGlm(p.position));
    m = glm::rotate(m, glm::radians(static_cast<float>(p.yawDegrees)), glm::vec3(0.0f, 1.0f, 0.0f));
    return glm::scale(m, glm::vec3(static_cast<float>(p.scale)));
}

Sculpture::Sculpture() = default;
Sculpture::~Sculpture() = default;
Sculpture::Sculpture(Sculpture&&) noexcept = default;
Sculpture& Sculpture::operator=(Sculpture&&) noexcept = default;

glm::mat4 Sculpture::modelToWorld() const { return placementMatrix(placement); }

glm::vec3 Sculpture::worldCentre() const {
    if (!volume) return glm::vec3(modelToWorld()[3]);
    const frep::Box3& b = volume->frame.modelBox;
    const glm::vec4 c(0.5 * (b.lo[0] + b.hi[0]), 0.5 * (b.lo[1] + b.hi[1]), 0.5 * (b.lo[2] + b.hi[2]), 1.0);
    return glm::vec3(modelToWorld() * c);
}

void GardenSession::resetView() {
    const Garden& g = *load_.garden;
    const glm::vec3 eye = toGlm(g.start.position);
    const glm::vec3 at = toGlm(g.start.lookAt);
    glm::vec3 dir = at - eye;
    if (glm::length(dir) < 1e-6f) dir = glm::vec3(0.0f, 0.0f, -1.0f);
    dir = glm::normalize(dir);
    navigator_.setMode(NavigationMode::Walk);
    navigator_.setPose(eye, std::atan2(dir.x, -dir.z), std::asin(std::clamp(dir.y, -1.0f, 1.0f)));
}

voxel::VolumeRequest GardenSession::volumeRequest(const SculptureSpec& spec) {
    voxel::VolumeRequest request;
    request.box = spec.box;
    request.resolution = spec.resolution;
    request.band = spec.band;
    return request;
}

GardenSession::GardenSession(GardenLoad load, SessionSettings settings)
    : load_(std::move(load)),
      settings_(settings),
      pager_(std::make_unique<GridPager>(settings.memoryBudgetBytes, settings.pageFolder)),
      scheduler_(settings.scheduler) {
    if (settings_.sculptureResolution > 0)
        for (SculptureSpec& spec : load_.garden->sculptures) spec.resolution = settings_.sculptureResolution;
    if (settings_.morphResolution > 0)
        for (MorphSpec& m : load_.garden->morphs) m.resolution = settings_.morphResolution;
    const Garden& g = *load_.garden;
    resetView();
    sculptures_.resize(g.sculptures.size());
    std::vector<std::size_t> now, later;
    for (std::size_t i = 0; i < g.sculptures.size(); ++i) {
        describeSculpture(i);
        if (sculptures_[i].missing()) continue;
        // Progressive: only the morphs' sources now (the blends need their grids).
        (settings_.progressiveLoading && !isMorphSource(g, i) ? later : now).push_back(i);
    }
    // Sculptures are independent: built side by side (each one's box
    // estimate runs on one thread), each into its own slot.
    tbb::parallel_for(std::size_t{0}, now.size(), [this, &now](std::size_t k) { sampleSculpture(now[k]); });
    for (std::size_t m = 0; m < g.morphs.size(); ++m) buildMorph(m);
    if (!later.empty()) {
        std::vector<SculptureLoader::Job> jobs;
        for (std::size_t i : later) {
            sculptures_[i].loading = true;
            const glm::vec3 at = sculptures_[i].worldCentre();
            jobs.push_back({i, std::make_shared<const SculptureLoad>(load_.sculptures[i]), g.sculptures[i],
                            volumeRequest(g.sculptures[i]), {at.x, at.y, at.z}});
        }
        const glm::vec3 eye = navigator_.eye();
        loader_ = std::make_unique<SculptureLoader>(std::move(jobs), std::array<double, 3>{eye.x, eye.y, eye.z},
                                                    meshingShape());
    }
    recorded_ = 0;  // the garden's own first weights are no action of the user's
    fileSculptures_ = g.sculptures.size();
    for (std::size_t i = 0; i < fileSculptures_; ++i) sculptures_[i].sourceStamp = sourceStamp(g.sculptures[i].file);
}

GardenSession::~GardenSession() = default;

int GardenSession::findSculpture(const std::string& name) const {
    for (std::size_t i = 0; i < sculptures_.size(); ++i)
        if (sculptures_[i].name == name && !sculptures_[i].removed) return static_cast<int>(i);
    return -1;
}

std::array<double, 3> GardenSession::toModel(const Sculpture& s, const glm::vec3& world) const {
    const glm::vec4 m = glm::inverse(s.modelToWorld()) * glm::vec4(world, 1.0f);
    return {m.x, m.y, m.z};
}

std::array<double, 3> GardenSession::toModelDirection(const Sculpture& s, const std::array<double, 3>& world) {
    // The placement's scale is uniform, and a direction's length does not matter.
    const glm::dvec3 n =
        glm::dvec3(glm::inverse(glm::dmat4(s.modelToWorld())) * glm::dvec4(world[0], world[1], world[2], 0.0));
    return {n.x, n.y, n.z};
}

// Builds the pyramid, layout and queue of a sampled sculpture, at the levels
// the start pose selects.
// `prepared`, when built (by the loader, on this very grid), is taken
// as it is.
void GardenSession::attachMeshing(Sculpture& s, PreparedMeshing prepared) const {
    const SessionSettings& settings = settings_;
    if (!prepared.pyramid) prepared = prepareMeshing(*s.volume, meshingShape());
    s.pyramid = std::move(prepared.pyramid);
    s.layout = std::move(prepared.layout);
    s.errors = std::move(prepared.errors);
    s.queue = std::make_unique<poly::RemeshQueue>(*s.pyramid, *s.layout,
                                                  std::vector<int>(s.layout->count(), settings.maxLevel));
    s.uniformLevel = settings.maxLevel;
    s.levelsChosen = LevelsChosen{};
    // The coarsest level at once (cheap: a few cells per chunk), so the
    // garden opens with every sculpture on show; finer levels then stream
    // in within the frame budget.
    s.queue->process(poly::RemeshBudget{});
}

MeshingShape GardenSession::meshingShape() const {
    return {settings_.maxLevel + 1, settings_.chunkSize, settings_.levelErrorPixels > 0.0};
}

void GardenSession::describeSculpture(std::size_t index) {
    const SculptureSpec& spec = load_.garden->sculptures[index];
    Sculpture& s = sculptures_[index];
    s.name = spec.name;
    s.source.kind = spec.scan   ? SculptureSource::Kind::Scan
                    : spec.mesh ? SculptureSource::Kind::Mesh
                                : SculptureSource::Kind::HyperFun;
    s.source.spec = static_cast<int>(index);
    s.placement = spec.placement;
    s.material = spec.material;
    const SculptureLoad& l = load_.sculptures[index];
    s.source.program = l.program;
    if (!l.ok()) s.error = l.error.empty() ? "the sculpture could not be loaded" : l.error;
}

void GardenSession::sampleSculpture(std::size_t index) {
    const SculptureSpec& spec = load_.garden->sculptures[index];
    voxel::VoxelizeResult r = sampleSculptureSource(spec, load_.sculptures[index], volumeRequest(spec));
    attachGrid(index, r.volume ? std::make_unique<voxel::Volume>(std::move(*r.volume)) : nullptr, r.error);
}

void GardenSession::attachGrid(std::size_t index, std::unique_ptr<voxel::Volume> volume, const std::string& error,
                               PreparedMeshing prepared) {
    Sculpture& s = sculptures_[index];
    s.loading = false;
    if (!volume) {
        s.error = error.empty() ? "the sculpture could not be sampled" : error;
        return;
    }
    s.volume = std::move(volume);
    attachMeshing(s, std::move(prepared));
}

void GardenSession::attachLoaded() {
    if (!loader_) return;
    const glm::vec3 eye = navigator_.eye();
    loader_->setViewer({eye.x, eye.y, eye.z});
    // At least one grid a frame (its coarse meshes come with it), more
    // while half the remesh allowance lasts: the rest is for finer levels;
    // none while the pager is writing grids out to come within the budget.
    if (pager_->backlog()) return;
    const double until = scheduler_.elapsedMs() + 0.5 * scheduler_.allowanceMs(Stage::Remesh);
    for (std::size_t n = 0;; ++n) {
        if (n > 0 && scheduler_.elapsedMs() >= until) break;
        std::vector<SculptureLoader::Loaded> got = loader_->take(1);
        if (got.empty()) break;
        attachGrid(got[0].sculpture, std::move(got[0].volume), got[0].error, std::move(got[0].meshing));
    }
    if (loader_->remaining() == 0) loader_.reset();
}

void GardenSession::finishLoading() {
    if (!loader_) return;
    loader_->wait();
    for (SculptureLoader::Loaded& l : loader_->take())
        attachGrid(l.sculpture, std::move(l.volume), l.error, std::move(l.meshing));
    loader_.reset();
}

std::size_t GardenSession::sculpturesLoading() const { return loader_ ? loader_->remaining() : 0; }

void GardenSession::buildMorph(std::size_t spec) {
    const MorphSpec& m = load_.garden->morphs[spec];
    Sculpture result;
    result.name = m.resultName;
    result.source.kind = SculptureSource::Kind::Morph;
    result.source.spec = static_cast<int>(spec);
    result.placement = m.resultPlacement;
    result.material = m.material;
    // The sources were sampled as sculptures: their boxes are known.
    MorphSourcesResult built = buildGardenMorphSources(load_, spec, 0, sampledModelBoxes(sculptures_));
    if (!built.sources) {
        result.error = built.error;
        sculptures_.push_back(std::move(result));
        return;
    }
    auto state = std::make_unique<MorphState>();
    state->sources = std::make_unique<MorphSources>(std::move(*built.sources));
    state->balance = morphBalance(m, *state->sources);
    result.volume = std::make_unique<voxel::Volume>(makeMorphVolume(*state->sources));
    attachMeshing(result);
    state->blender = std::make_unique<MorphBlender>(*state->sources, *result.volume);
    result.morph = std::move(state);
    const int index = static_cast<int>(sculptures_.size());
    sculptures_.push_back(std::move(result));
    // Its first weights: the file's selector (no action of the user's).
    MorphState& made = *sculptures_.back().morph;
    made.weights = hg::garden::morphWeights(*morphTriangle(index), {m.selector[0], m.selector[1]}, made.balance);
    restartMorph(index);
    if (activeMorph_ < 0) activeMorph_ = index;
}

std::vector<int> GardenSession::morphResults() const {
    std::vector<int> out;
    for (std::size_t i = 0; i < sculptures_.size(); ++i)
        if (sculptures_[i].morphResult()) out.push_back(static_cast<int>(i));
    return out;
}

void GardenSession::setActiveMorph(int sculpture) {
    if (sculpture >= 0 && sculpture < static_cast<int>(sculptures_.size()) &&
        sculptures_[static_cast<std::size_t>(sculpture)].morph)
        activeMorph_ = sculpture;
}

const MorphState* GardenSession::morphState(int sculpture) const {
    const Sculpture* s = morphResultAt(sculptures_, sculpture, activeMorph_);
    return s ? s->morph.get() : nullptr;
}

MorphState* GardenSession::morphState(int sculpture) {
    return const_cast<MorphState*>(static_cast<const GardenSession*>(this)->morphState(sculpture));
}

const std::optional<MorphWeights>& GardenSession::morphWeights(int sculpture) const {
    static const std::optional<MorphWeights> none;
    const MorphState* m = morphState(sculpture);
    return m ? m->weights : none;
}

const MorphSpec* GardenSession::morphSpec(int sculpture) const {
    const Sculpture* s = morphResultAt(sculptures_, sculpture, activeMorph_);
    return s ? &load_.garden->morphs[static_cast<std::size_t>(s->source.spec)] : nullptr;
}

std::optional<MorphTriangle> GardenSession::morphTriangle(int sculpture) const {
    const Sculpture* s = morphResultAt(sculptures_, sculpture, activeMorph_);
    if (!s) return std::nullopt;
    return hg::garden::morphTriangle(*load_.garden, static_cast<std::size_t>(s->source.spec));
}

void GardenSession::setActiveWeights(const MorphWeights& w) {
    MorphState* m = morphState(activeMorph_);
    if (!m) return;
    m->weights = w;
    restartMorph(activeMorph_);
    recordMorph(activeMorph_);
}

void GardenSession::setMorphPoint(double x, double z) {
    if (const MorphState* m = morphState(activeMorph_))
        setActiveWeights(hg::garden::morphWeights(*morphTriangle(activeMorph_), {x, z}, m->balance));
}

void GardenSession::setMorphWeights(const std::array<double, 3>& w) {
    if (!morphState(activeMorph_)) return;
    const double sum = w[0] + w[1] + w[2];
    setActiveWeights(weightsFromBarycentric({w[0] / sum, w[1] / sum, w[2] / sum}));
}

void GardenSession::setMorphBarycentric(const std::array<double, 3>& b) {
    const MorphState* m = morphState(activeMorph_);
    if (!m) return;
    const double sum = b[0] + b[1] + b[2];
    setActiveWeights(weightsFromBarycentric({b[0] / sum, b[1] / sum, b[2] / sum}, m->balance));
}

void GardenSession::recordMorph(int sculpture) {
    if (morphDragging_) {
        morphDragged_ = true;  // journalled when the hand lets go
        return;
    }
    const MorphWeights& w = *morphState(sculpture)->weights;
    record(MorphWeightsAction{w.barycentric, w.balance, sculptures_[static_cast<std::size_t>(sculpture)].name});
}

void GardenSession::record(const Action& r) {
    if (restoring_) return;
    ++recorded_;
    if (journal_) journal_->append(r);
}

void GardenSession::restartMorph(int sculpture) {
    const Sculpture& r = sculptures_[static_cast<std::size_t>(sculpture)];
    r.morph->blender->restart(*r.morph->weights, toModel(r, navigator_.eye()));
}

void GardenSession::select(int sculpture) {
    selected_ = sculpture >= 0 && sculpture < static_cast<int>(sculptures_.size()) &&
                        !sculptures_[static_cast<std::size_t>(sculpture)].removed
                    ? sculpture
                    : -1;
    setActiveMorph(selected_);  // a morph result selected is the one the selector steers
    navigator_.setOrbitTarget(selected_ >= 0 ? std::optional<glm::vec3>(sculptures_[static_cast<std::size_t>(selected_)].worldCentre())
                                             : std::nullopt);
    if (selected_ < 0 && navigator_.mode() == NavigationMode::Orbit) navigator_.setMode(NavigationMode::Walk);
}

const FrameStats& GardenSession::frame(const FrameInput& in) {
    NullViewSink none;
    return frame(in, none);
}

const FrameStats& GardenSession::frame(const FrameInput& in, ViewSink& views) {
    beginFrame();
    Hands hands = in.hands;
    if (in.commands && !in.commands(*this, hands)) return endFrame();
    input(hands, in.dt);
    selectLevels();
    morph();
    remesh();
    uploadAndRender(views);
    return endFrame();
}

void GardenSession::beginFrame() {
    scheduler_.beginFrame();
    scheduler_.beginStage(Stage::Input);
}

void GardenSession::uploadAndRender(ViewSink& views) {
    scheduler_.beginStage(Stage::Upload);
    const ViewUpload up = views.upload(*this, scheduler_.allowanceMs(Stage::Upload));
    stats().uploadBytes += up.bytes;
    stats().uploadsPending = up.pending;
    scheduler_.beginStage(Stage::Render);
    const ViewDraw drawn = views.render(*this);
    stats().trianglesDrawn = drawn.trianglesDrawn;
    stats().chunksDrawn = drawn.chunksDrawn;
    stats().drawCalls = drawn.drawCalls;
    stats().gpuMs = drawn.gpuMs;
    stats().gpuPassMs = drawn.gpuPassMs;
    stats().impostorsDrawn = drawn.impostorsDrawn;
    stats().sculpturesHidden = drawn.sculpturesHidden;
    stats().shadowMapsDrawn = drawn.shadowMapsDrawn;
    stats().shadowMapsKept = drawn.shadowMapsKept;
    stats().picturesKept = drawn.picturesKept;
    stats().picturesSharpened = drawn.picturesSharpened;
}

void GardenSession::input(const Hands& hands, double dt) {
    scheduler_.beginStage(Stage::Input);
    // First the edits that wait, so that the tools see the grid as whole as
    // this frame can make it.
    advanceEdits(scheduler_.allowanceMs(Stage::Input));
    navigator_.update(hands, dt);
    applyToolIntents(hands);
    sculptWithHands(hands);
    advanceEdits(0.0);  // what the tools settled, shown in this frame
    if (tool_.kind != ToolSettings::Kind::None) return;  // the trigger sculpts
    // The tool's ray on the morph triangle drawn on the ground picks the
    // blend (seed 004's selector), while the trigger is held.
    morphDragging_ = activeMorph_ >= 0 && hands.tool.tracked && hands.tool.trigger > 0.5f;
    if (!morphDragging_ && morphDragged_) {
        morphDragged_ = false;
        recordMorph(morphDragTarget_);
    }
    if (!morphDragging_) morphDragTarget_ = -1;
    if (morphDragging_) {
        if (const auto hit = hands.tool.aim.groundHit(load_.garden->ground.height)) {
            const Point2 p{hit->x, hit->z};
            // The drag steers the morph whose triangle it began on (or just
            // beside): the nearest, when several are within reach.
            if (morphDragTarget_ < 0) {
                double nearest = kMorphPickReach;
                for (int r : morphResults()) {
                    if (!sculptures_[static_cast<std::size_t>(r)].morph) continue;
                    const Point2 q = clampToTriangle(*morphTriangle(r), p);
                    const double dist = std::hypot(p[0] - q[0], p[1] - q[1]);
                    if (dist < nearest) nearest = dist, morphDragTarget_ = r;
                }
            }
            if (morphDragTarget_ >= 0) {
                const Point2 q = clampToTriangle(*morphTriangle(morphDragTarget_), p);
                const double dist = std::hypot(p[0] - q[0], p[1] - q[1]);
                const auto& w = morphWeights(morphDragTarget_);
                const bool moved = !w || std::hypot(q[0] - w->point[0], q[1] - w->point[1]) > 0.01;
                activeMorph_ = morphDragTarget_;
                if (dist < kMorphPickReach && moved) setMorphPoint(q[0], q[1]);  // on the triangle, or just beside it
            }
        }
    }
}

void GardenSession::selectLevels() {
    scheduler_.beginStage(Stage::Lod);
    gridNeeds_.assign(sculptures_.size(), GridNeed{});
    const double refreshUntil = scheduler_.elapsedMs() + settings_.errorRefreshMs;
    bool refreshed = false;
    for (std::size_t index = 0; index < sculptures_.size(); ++index) {
        Sculpture& s = sculptures_[index];
        if (!s.onShow()) continue;
        const std::array<double, 3> eye = toModel(s, navigator_.eye());
        s.queue->setViewer(eye);
        // At least one batch a frame, whatever the time: idle() waits for
        // every error, so a frame whose allowance went before reaching the
        // unknown ones must still make progress.
        if (errorsWaiting(s)) {
            const double left = refreshUntil - scheduler_.elapsedMs();
            if (left > 0.0 || !refreshed) s.errors->refresh(eye, std::max(left, 1e-6));  // 0 would mean all
            refreshed = true;
        }
        poly::Camera cam;
        cam.position = eye;
        cam.fovY = settings_.fovY;
        cam.viewportHeight = settings_.viewportHeight;
        poly::LodSettings lod;
        lod.pixelError = settings_.pixelError;
        lod.maxLevel = settings_.maxLevel;
        lod.errorPixels = settings_.levelErrorPixels;
        if (detail_) {
            const glm::vec3 c(static_cast<float>(detail_->center[0]), static_cast<float>(detail_->center[1]),
                              static_cast<float>(detail_->center[2]));
            lod.detail = poly::Sphere{toModel(s, c), detail_->radius / s.scale()};
        }
        GridNeed& need = gridNeeds_[index] = gridNeed(index, cam, lod);
        // New levels go to a queue once it has shown the last ones, or at
        // most every half second of frames: while the viewer walks, levels
        // change every frame, and a queue that took each change would keep
        // growing its group of dirty chunks and never show it. Yet a long
        // morph re-blend keeps the result's queue busy, and its levels must
        // still follow the viewer.
        if (s.queue->pending() > 0 && ++s.framesSinceLevels < kLevelRefreshFrames) continue;
        s.framesSinceLevels = 0;
        // The sculpture first (poly::uniformLevel): one level for all its
        // chunks when its bound says so, and nothing to do when that is the
        // level it has; its chunks are visited only when their levels differ.
        // A grid on disk keeps its chunks at level 1 or coarser (its coarse
        // levels are in memory) until the pager has it back.
        const int finest = s.volume->resident() ? 0 : 1;
        std::optional<int> uniform = settings_.lod ? poly::uniformLevel(*s.layout, cam, lod, s.errors.get()) : 0;
        if (uniform) {
            need.wanted = need.wanted || *uniform == 0;
            uniform = std::max(*uniform, finest);
        }
        if (uniform && *uniform == s.uniformLevel) continue;
        LevelsChosen& chosen = s.levelsChosen;
        LevelsChosen now{true, eye, s.errors ? s.errors->version() : 0, {0.0, 0.0, 0.0, -1.0}, finest, false};
        if (lod.detail) now.detail = {lod.detail->center[0], lod.detail->center[1], lod.detail->center[2], lod.detail->radius};
        now.view = {static_cast<double>(cam.viewportHeight), cam.fovY, lod.pixelError, lod.errorPixels,
                    static_cast<double>(lod.maxLevel)};
        if (!uniform && chosen.sameInputs(now) &&
            glm::distance(glm::dvec3(eye[0], eye[1], eye[2]), glm::dvec3(chosen.eye[0], chosen.eye[1], chosen.eye[2])) <=
                kReselectMove * need.distance / s.scale()) {  // gridNeed's distanceToBound
            need.wanted = need.wanted || chosen.anyFull;
            continue;
        }
        std::vector<int> levels;
        if (uniform) {
            levels.assign(s.layout->count(), *uniform);
            chosen = LevelsChosen{};
        } else {
            levels = poly::selectLevelsPerChunk(*s.layout, cam, lod, s.errors.get());
            stats().lodChunksVisited += s.layout->count();
            chosen = now;
            for (int& l : levels) {
                chosen.anyFull = chosen.anyFull || l == 0;
                l = std::max(l, finest);
            }
            need.wanted = need.wanted || chosen.anyFull;
        }
        s.uniformLevel = uniform ? *uniform : -1;
        s.queue->setLevels(levels);
    }
    pager_->step(sculptures_, gridNeeds_);
}

GridNeed GardenSession::gridNeed(std::size_t index, const poly::Camera& camera, const poly::LodSettings& lod) const {
    const Sculpture& s = sculptures_[index];
    GridNeed need;
    const double nearest = distanceToBound(*s.layout, camera.position);
    need.distance = nearest * s.scale();
    const double h = s.layout->frame().voxelSize;
    const int i = static_cast<int>(index);
    const bool inUse = i == selected_ || i == strokeSculpture_ || i == liveMove_ || (moveDrag_ && moveDrag_->sculpture == i);
    need.wanted = !settings_.lod || inUse || poly::levelAtDistance(camera, h, nearest / kBringBackMargin, lod) == 0;
    // Only a grid that is a pure function of its source may go (edits and
    // blends live in theirs), once every chunk shows level 1 or coarser.
    need.mayGo = !need.wanted && !s.edits && !s.morph && !s.morphResult() && s.uniformLevel >= 1 &&
                 s.queue->pending() == 0 && !s.queue->meshing() &&
                 poly::levelAtDistance(camera, h, nearest / kLetGoMargin, lod) >= 1;
    return need;
}

void GardenSession::settlePaging() {
    if (gridNeeds_.size() != sculptures_.size()) gridNeeds_.resize(sculptures_.size());
    pager_->settle(sculptures_, gridNeeds_);
}

void GardenSession::morph() {
    scheduler_.beginStage(Stage::Morph);
    // Every morph that has blending left shares the stage's budget, each
    // taking what the ones before it left: the active one first (the one
    // the user steers answers first), then the others in the garden's order.
    std::vector<int> order = morphResults();
    std::stable_partition(order.begin(), order.end(), [this](int r) { return r == activeMorph_; });
    std::uint64_t samplesLeft = settings_.morphSamplesPerFrame;
    const bool offThread = settings_.morphSamplesPerFrame == 0 && settings_.workOffFrameThread;
    const double until = scheduler_.elapsedMs() + scheduler_.allowanceMs(Stage::Morph);
    bool first = true;
    for (int index : order) {
        Sculpture& r = sculptures_[static_cast<std::size_t>(index)];
        if (!r.morph || r.morph->blender->done()) continue;
        BlendBudget budget;
        if (settings_.morphSamplesPerFrame > 0) {
            if (samplesLeft == 0) break;
            budget.maxSamples = samplesLeft;
        } else {
            budget.maxSamples = 0;
            const double left = until - scheduler_.elapsedMs();
            if (left <= 0.0 && !first) {
                // Off the frame thread a morph with no time left still hands
                // the thread its next batch (which costs nothing here), after
                // writing at most one block.
                if (!offThread) break;
                budget.maxSamples = 1;
            }
            budget.maxMilliseconds = std::max(left, 0.01);  // 0 would mean no limit
        }
        first = false;
        // Each batch's changes are shown within the step, so the time they
        // take counts against the stage's allowance.
        budget.commit = [&r](const std::vector<voxel::IndexBox>& changed) {
            for (const voxel::IndexBox& box : changed) {
                if (r.edits) r.edits->baseChanged(box);  // the blend changed under the edits
                r.pyramid->update(box);
                if (r.errors) r.errors->update(box);
                r.queue->markChanged(box);
            }
        };
        r.morph->blender->setViewer(toModel(r, navigator_.eye()));
        BlendStep step;
        if (offThread) {
            if (!blending_) blending_ = std::make_unique<jobs::JobThread>();
            step = r.morph->blender->stepInBackground(budget, *blending_);
        } else {
            step = r.morph->blender->step(budget);
        }
        stats().morphSamples += step.samples;
        samplesLeft -= std::min(samplesLeft, step.samples);
    }
}

void GardenSession::remesh() {
    scheduler_.beginStage(Stage::Remesh);
    attachLoaded();
    // Nearest sculpture first: its chunks matter most on screen.
    std::vector<std::pair<float, std::size_t>> order;
    for (std::size_t i = 0; i < sculptures_.size(); ++i)
        if (sculptures_[i].onShow() && sculptures_[i].queue->pending() > 0)
            order.emplace_back(glm::length(sculptures_[i].worldCentre() - navigator_.eye()), i);
    std::sort(order.begin(), order.end());
    if (settings_.remeshChunksPerFrame == 0 && settings_.workOffFrameThread) {
        remeshInBackground(order);
        return;
    }
    bool meshed = false;
    std::size_t chunksLeft = settings_.remeshChunksPerFrame;
    for (const auto& [distance, i] : order) {
        poly::RemeshBudget budget;
        limitShownBytes(budget, settings_.uploadBytesPerFrame, stats());
        if (settings_.remeshChunksPerFrame > 0) {
            if (chunksLeft == 0) break;
            budget.chunks = chunksLeft;
        } else {
            budget.milliseconds = scheduler_.allowanceMs(Stage::Remesh);
            if (meshed && budget.milliseconds <= scheduler_.settings().minimumMs) break;
        }
        const poly::RemeshReport r = sculptures_[i].queue->process(budget);
        addRemeshReport(stats(), r);
        meshed = meshed || r.meshed > 0;
        chunksLeft -= std::min(chunksLeft, r.meshed);
    }
}

// The frame gathers samples and shows finished meshes; the worker meshes.
// Gathering is a small part of a mesh's cost, so a frame gathers for at
// most a millisecond (the nearest sculptures first), and only while the
// worker has fewer than two jobs waiting: more would be meshed too late to
// matter, from samples that edits and level changes may already have made
// stale.
void GardenSession::remeshInBackground(const std::vector<std::pair<float, std::size_t>>& order) {
    constexpr double kGatherMs = 1.0;
    constexpr std::size_t kJobsAhead = 2;
    if (!meshing_) meshing_ = std::make_unique<poly::MeshingWorker>();
    const double allowance = std::min(kGatherMs, scheduler_.allowanceMs(Stage::Remesh));
    const auto start = std::chrono::steady_clock::now();
    for (const auto& entry : order) {
        const double spent =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        poly::RemeshBudget budget;
        budget.gather = spent < allowance && meshing_->backlog() < kJobsAhead;
        budget.milliseconds = std::max(0.05, allowance - spent);
        limitShownBytes(budget, settings_.uploadBytesPerFrame, stats());
        addRemeshReport(stats(), sculptures_[entry.second].queue->processInBackground(*meshing_, budget));
    }
}

const FrameStats& GardenSession::endFrame() {
    FrameStats& st = stats();
    st.remeshPending = remeshPending();
    st.trianglesShown = trianglesShown();
    st.morphPending = morphRemaining();
    st.sculpturesLoading = sculpturesLoading();
    return scheduler_.endFrame();
}

std::size_t GardenSession::remeshPending() const {
    std::size_t n = 0;
    for (const Sculpture& s : sculptures_)
        if (s.onShow()) n += s.queue->pending();
    return n;
}

std::uint64_t GardenSession::morphRemaining() const {
    std::uint64_t n = 0;
    for (const Sculpture& s : sculptures_)
        if (s.morph) n += s.morph->blender->remainingSamples();
    return n;
}

std::size_t GardenSession::trianglesShown() const {
    std::size_t n = 0;
    for (const Sculpture& s : sculptures_)
        if (s.onShow()) n += s.queue->shownTriangles();
    return n;
}

bool GardenSession::idle() const {
    const bool editsLate = std::any_of(sculptures_.begin(), sculptures_.end(),
                                       [](const Sculpture& s) { return s.edits && s.edits->late(); });
    const bool blending =
        std::any_of(sculptures_.begin(), sculptures_.end(), [](const Sculpture& s) { return s.morph && !s.morph->blender->done(); });
    // A level choice put off while the queue was busy, or errors still to be
    // measured after an edit or a blend (their chunks take the voxel-size
    // rule's finer levels meanwhile), would leave levels that depend on the
    // frames' timing.
    const bool levelsLate = std::any_of(sculptures_.begin(), sculptures_.end(), [](const Sculpture& s) {
        return s.onShow() && (s.framesSinceLevels > 0 || errorsWaiting(s));
    });
    return !blending && !editsLate && !levelsLate && remeshPending() == 0 && sculpturesLoading() == 0;
}

void GardenSession::advanceEdits(double milliseconds) {
    for (std::size_t i = 0; i < sculptures_.size(); ++i) {
        Sculpture& s = sculptures_[i];
        if (!s.edits || !s.edits->late()) continue;
        // What the first sculpture used comes off the others' time.
        const auto start = std::chrono::steady_clock::now();
        for (const voxel::IndexBox& box : s.edits->advance(milliseconds)) showChanged(static_cast<int>(i), box);
        milliseconds -= std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        milliseconds = std::max(milliseconds, 0.0);
    }
}

void GardenSession::settleEdits() { advanceEdits(std::numeric_limits<double>::infinity()); }

const voxel::Volume* GardenSession::morphResult(int sculpture) const {
    const Sculpture* s = morphResultAt(sculptures_, sculpture, activeMorph_);
    return s ? s->volume.get() : nullptr;
}

std::unique_ptr<voxel::Volume> GardenSession::blendFromScratch(int sculpture) const {
    const MorphState* m = morphState(sculpture);
    if (!m) return nullptr;
    return std::make_unique<voxel::Volume>(blendMorph(*m->sources, *m->weights));
}

const MorphSources* GardenSession::morphSources(int sculpture) const {
    const MorphState* m = morphState(sculpture);
    return m ? m->sources.get() : nullptr;
}

}  // namespace hg::garden
