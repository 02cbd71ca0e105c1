#include "garden/render/renderer.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cstring>
#include <cmath>
#include <stdexcept>
#include <string>

#include "garden/render/chunk_batch.h"
#include "garden/render/gpu_timers.h"
#include "garden/render/held_output.h"
#include "garden/render/occlusion_pass.h"
#include "garden/render/visibility_queries.h"
#include "garden/render/post_process.h"
#include "garden/render/render_targets.h"
#include "garden/render/shaders.h"
#include "garden/render/shadow_pass.h"
#include "garden/render/shapes.h"
#include "garden/render/sky_pass.h"

namespace hg::garden {

// shaders.cpp declares the light arrays with these sizes.
static_assert(kMaxLights == 3, "uLightDir[3] in shaders.cpp");
static_assert(kMaxPointLights == 8, "uPointPosition[8] in shaders.cpp");

namespace {

// Fraction of the eye distance by which lines and the sphere are pulled
// nearer: a centimetre at 10 m, a hundred times the 24-bit depth step there
// with a 5 cm near plane, and too little to show through a sculpture.
constexpr float kDepthPull = 1e-3f;
constexpr float kGroundOffsetFactor = 1.0f;
constexpr float kGroundOffsetUnits = 1.0f;
constexpr int kSphereSlices = 48;
constexpr int kSphereStacks = 24;
constexpr int kCircleSegments = 96;
// The wireframe overlay's lines (sRGB, over the tone-mapped picture): dark
// enough to read on plaster, light enough that bronze shows through.
const glm::vec4 kEdgeColor{0.05f, 0.06f, 0.08f, 0.55f};

const void* byteOffset(std::size_t bytes) { return reinterpret_cast<const void*>(bytes); }

template <typename T>
GLsizeiptr byteSize(const std::vector<T>& v) {
    return static_cast<GLsizeiptr>(v.size() * sizeof(T));
}

void checkMesh(const poly::Mesh& mesh) {
    if (mesh.positions.size() % 3 != 0) throw std::invalid_argument("mesh positions are not xyz triples");
    if (!mesh.normals.empty() && mesh.normals.size() != mesh.positions.size())
        throw std::invalid_argument("mesh normals and positions differ in length");
    if (mesh.indices.size() % 3 != 0) throw std::invalid_argument("mesh indices are not triangles");
    const std::size_t vertices = mesh.vertexCount();
    // An index past the end would have the GPU read outside the buffer.
    std::uint32_t top = 0;
    for (std::uint32_t i : mesh.indices) top = i > top ? i : top;
    if (!mesh.indices.empty() && top >= vertices)
        throw std::invalid_argument("mesh index " + std::to_string(top) + " past the last of " +
                                    std::to_string(vertices) + " vertices");
}

void setMat4(GLint location, const glm::mat4& m) { glUniformMatrix4fv(location, 1, GL_FALSE, glm::value_ptr(m)); }

glm::vec3 srgbToLinear(const glm::vec3& c) {
    glm::vec3 out;
    for (int i = 0; i < 3; ++i)
        out[i] = c[i] <= 0.04045f ? c[i] / 12.92f : std::pow((c[i] + 0.055f) / 1.055f, 2.4f);
    return out;
}

// A chunk draw's record for the shaders (HG_DRAW_RECORD_GLSL in shaders.h):
// the transform, the normal transform (the inverse transpose, for scales
// that are not uniform) and the material. The one place the mesh program's
// material inputs are set.
DrawRecord drawRecord(const glm::mat4& model, const RenderMaterial& material, bool hasNormals) {
    DrawRecord r{};
    for (int c = 0; c < 4; ++c) r[static_cast<std::size_t>(c)] = model[c];
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(model)));
    for (int c = 0; c < 3; ++c) r[static_cast<std::size_t>(4 + c)] = glm::vec4(normalMatrix[c], 0.0f);
    r[7] = glm::vec4(material.baseColor, material.specular);
    r[8] = glm::vec4(material.shininess, hasNormals ? 1.0f : 0.0f, std::clamp(material.cavity, 0.0f, 1.0f), 0.0f);
    r[9] = glm::vec4(static_cast<float>(material.kind), material.metallic,
                     material.detailScale > 0.0f ? material.detailScale : 1.0f, 0.0f);
    return r;
}

// The same impostor cards, byte for byte (plain floats).
bool sameCards(const std::vector<ImpostorCard>& a, const std::vector<ImpostorCard>& b) {
    return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(ImpostorCard)) == 0);
}

// The texture unit the lit programs read the shadow map from.
constexpr GLint kShadowUnit = 3;
// Metres between the 3 x 3 shadow taps: a penumbra of about 5 cm.
constexpr float kPenumbraStep = 0.02f;

}  // namespace

float RenderStats::gpuMs() const {
    float sum = 0.0f;
    bool any = false;
    for (float ms : {gpuShadowMs, gpuSceneMs, gpuOcclusionMs, gpuPostMs})
        if (ms >= 0.0f) {
            sum += ms;
            any = true;
        }
    return any ? sum : -1.0f;
}

Renderer::Renderer()
    : groundProgram_("ground", shaders::kGroundVertex, shaders::kGroundFragment),
      flatProgram_("flat", shaders::kFlatVertex, shaders::kFlatFragment),
      targets_(std::make_unique<SceneTargets>()),
      shadow_(std::make_unique<ShadowPass>()),
      occlusion_(std::make_unique<OcclusionPass>()),
      sky_(std::make_unique<SkyPass>()),
      post_(std::make_unique<PostProcess>()),
      timers_(std::make_unique<GpuTimers>()),
      arena_(std::make_unique<ChunkArena>()),
      shadowBatch_(std::make_unique<ChunkBatch>()),
      multiDraw_(multiDrawAvailable()),
      still_(std::make_unique<StillPicture>()) {
    for (auto& batch : batches_) batch = std::make_unique<ChunkBatch>();
    meshProgram(kSurfacePlain);  // a broken shader fails here, not mid-frame
    groundLit_ = litUniforms(groundProgram_);
    groundShadow_ = shadowUniforms(groundProgram_);
    const ShaderProgram& g = groundProgram_;
    ground_ = {g.uniform("uViewProjection"), g.uniform("uGroundColor"), g.uniform("uLineColor"),
               g.uniform("uSpacing"),        g.uniform("uLineWidth"),   g.uniform("uMajorEvery"),
               g.uniform("uGardenHalfExtent"), g.uniform("uGridReach"), g.uniform("uStripeWidth")};
    const ShaderProgram& f = flatProgram_;
    flat_ = {f.uniform("uModel"), f.uniform("uView"), f.uniform("uProjection"), f.uniform("uColor")};
    f.use();
    glUniform1f(f.uniform("uDepthPull"), kDepthPull);

    // GroundStyle: two triangles whose corners drawGround rewrites (72 bytes) for
    // the ground's extent.
    groundVao_ = gl::VertexArray::create();
    groundVbo_ = gl::Buffer::create();
    glBindVertexArray(groundVao_.get());
    glBindBuffer(GL_ARRAY_BUFFER, groundVbo_.get());
    glBufferData(GL_ARRAY_BUFFER, 6 * 3 * sizeof(float), nullptr, GL_DYNAMIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), byteOffset(0));

    streamVao_ = gl::VertexArray::create();
    streamVbo_ = gl::Buffer::create();
    glBindVertexArray(streamVao_.get());
    glBindBuffer(GL_ARRAY_BUFFER, streamVbo_.get());
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), byteOffset(0));

    const poly::Mesh sphere = uvSphereMesh(1.0f, kSphereSlices, kSphereStacks);
    sphereVao_ = gl::VertexArray::create();
    sphereVbo_ = gl::Buffer::create();
    sphereEbo_ = gl::Buffer::create();
    glBindVertexArray(sphereVao_.get());
    glBindBuffer(GL_ARRAY_BUFFER, sphereVbo_.get());
    glBufferData(GL_ARRAY_BUFFER, byteSize(sphere.positions), sphere.positions.data(), GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), byteOffset(0));
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, sphereEbo_.get());
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, byteSize(sphere.indices), sphere.indices.data(), GL_STATIC_DRAW);
    sphereIndexCount_ = static_cast<GLsizei>(sphere.indices.size());

    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
}

Renderer::~Renderer() = default;

namespace {
int surfaceKindIndex(int kind) { return std::clamp(kind, 0, kSurfaceKindCount - 1); }

// The mesh program compiled for surface `kind` (HG_KIND), with `defines`
// besides, reading the batches' draw records.
ShaderProgram meshProgramFor(const char* name, int kind, const std::string& defines) {
    ShaderProgram p(name, shaders::kMeshVertex,
                    withDefines(shaders::meshFragment(), defines + "#define HG_KIND " + std::to_string(kind) + "\n")
                        .c_str());
    p.use();
    glUniform1i(p.uniform("uDrawRecords"), kDrawRecordUnit);
    return p;
}
}  // namespace

Renderer::MeshProgram& Renderer::meshProgram(int kind) {
    std::unique_ptr<MeshProgram>& made = meshPrograms_[static_cast<std::size_t>(surfaceKindIndex(kind))];
    if (made) return *made;
    auto m = std::make_unique<MeshProgram>();
    m->program = meshProgramFor("mesh", surfaceKindIndex(kind), "");
    m->lit = litUniforms(m->program);
    m->shadow = shadowUniforms(m->program);
    m->viewProjection = m->program.uniform("uViewProjection");
    m->bump = m->program.uniform("uBump");
    made = std::move(m);
    return *made;
}

ShaderProgram& Renderer::bakeProgram(int kind) {
    std::unique_ptr<ShaderProgram>& made = bakePrograms_[static_cast<std::size_t>(surfaceKindIndex(kind))];
    // The mesh program itself, made to write what a frame holds instead of
    // lighting it: the impostor shows the very colours and relief.
    if (!made)
        made = std::make_unique<ShaderProgram>(meshProgramFor("impostor bake", surfaceKindIndex(kind), "#define HG_BAKE 1\n"));
    return *made;
}

Renderer::LitUniforms Renderer::litUniforms(const ShaderProgram& p) {
    return LitUniforms{p.uniform("uEye"),         p.uniform("uAmbient"),       p.uniform("uLightCount"),
                       p.uniform("uLightDir"),    p.uniform("uLightColor"),    p.uniform("uPointCount"),
                       p.uniform("uPointPosition"), p.uniform("uPointColor"), p.uniform("uPointRange"),
                       p.uniform("uHaze"),        p.uniform("uHazeDistance")};
}

Renderer::ShadowUniforms Renderer::shadowUniforms(const ShaderProgram& p) {
    p.use();
    glUniform1i(p.uniform("uShadowMap"), kShadowUnit);
    return ShadowUniforms{p.uniform("uShadows"), p.uniform("uShadowMatrix"), p.uniform("uShadowOffset"),
                          p.uniform("uShadowTexel")};
}

// --- impostors -------------------------------------------------------------------

void Renderer::ensureImpostors() {
    if (atlas_) return;
    atlas_ = std::make_unique<ImpostorAtlas>(impostorSettings_);
    cards_ = std::make_unique<ImpostorCards>();
    bakeBatch_ = std::make_unique<ChunkBatch>();
    cardLit_ = litUniforms(cards_->sceneProgram());
    cardShadow_ = shadowUniforms(cards_->sceneProgram());
    glUseProgram(0);
}

bool Renderer::hasImpostor(ImpostorKey key, std::uint64_t version) const {
    return atlas_ && atlas_->has(key, version);
}

bool Renderer::bakeImpostor(ImpostorKey key, std::uint64_t version, const std::vector<ChunkId>& ids,
                            const RenderMaterial& material) {
    ensureImpostors();
    bakeBatch_->clear();
    glm::vec3 lo(1e30f), hi(-1e30f);
    bool previousNormals = false;
    std::size_t record = 0;
    for (ChunkId id : ids) {
        auto found = chunks_.find(id);
        if (found == chunks_.end()) return false;
        const ChunkRecord& c = found->second;
        const ArenaSlot* slot = arena_->slot(id);
        if (c.indexCount == 0 || slot == nullptr) continue;
        if (bakeBatch_->empty() || c.hasNormals != previousNormals) {
            record = bakeBatch_->addRecord(drawRecord(glm::mat4(1.0f), material, c.hasNormals));
            previousNormals = c.hasNormals;
        }
        bakeBatch_->add(*slot, record);
        lo = glm::min(lo, c.lo);
        hi = glm::max(hi, c.hi);
    }
    if (bakeBatch_->empty()) return false;
    ShaderProgram& bake = bakeProgram(material.kind);
    bake.use();
    glUniform1f(bake.uniform("uBump"), quality_.materialBump ? 1.0f : 0.0f);
    const bool baked = atlas_->bake(key, version, *bakeBatch_, *arena_, multiDraw_, bake, 0.5f * (lo + hi),
                                    0.5f * glm::length(hi - lo));
    glUseProgram(0);
    if (baked) stats_.impostorsBaked += 1;
    return baked;
}

bool Renderer::drawImpostor(ImpostorKey key, std::uint64_t version, const glm::mat4& model,
                            const RenderMaterial& material) {
    if (!atlas_) return false;
    const ImpostorEntry* e = atlas_->use(key, version);
    if (e == nullptr) return false;
    ImpostorCard card;
    card.model = model;
    card.sphere = glm::vec4(e->centre, e->radius);
    card.look = glm::vec4(static_cast<float>(e->layer), material.specular, material.shininess, material.metallic);
    cardDraws_.push_back(card);
    stats_.impostorsDrawn += 1;
    stats_.trianglesDrawn += 2;
    return true;
}

// --- chunk buffers -----------------------------------------------------------

std::size_t Renderer::upload(ChunkId id, std::uint64_t version, const poly::Mesh& mesh) {
    auto found = chunks_.find(id);
    if (found != chunks_.end() && found->second.version == version) return 0;
    checkMesh(mesh);

    ChunkRecord& c = chunks_[id];
    residentBytes_ -= c.bytes;
    c.version = version;
    c.indexCount = mesh.indices.size();
    c.hasNormals = !mesh.normals.empty();
    // An empty mesh keeps the record (the chunk is current and empty) and
    // frees its space.
    c.bytes = arena_->place(id, mesh);
    if (mesh.empty()) return 0;

    c.lo = glm::vec3(mesh.positions[0], mesh.positions[1], mesh.positions[2]);
    c.hi = c.lo;
    for (std::size_t i = 0; i + 2 < mesh.positions.size(); i += 3) {
        const glm::vec3 p(mesh.positions[i], mesh.positions[i + 1], mesh.positions[i + 2]);
        c.lo = glm::min(c.lo, p);
        c.hi = glm::max(c.hi, p);
    }
    residentBytes_ += c.bytes;
    stats_.bytesUploaded += c.bytes;
    return c.bytes;
}

bool Renderer::has(ChunkId id, std::uint64_t version) const {
    auto found = chunks_.find(id);
    return found != chunks_.end() && found->second.version == version;
}

bool Renderer::has(ChunkId id) const { return chunks_.count(id) != 0; }

bool Renderer::bounds(ChunkId id, glm::vec3& lo, glm::vec3& hi) const {
    auto found = chunks_.find(id);
    if (found == chunks_.end() || found->second.indexCount == 0) return false;
    lo = found->second.lo;
    hi = found->second.hi;
    return true;
}

void Renderer::drop(ChunkId id) {
    auto found = chunks_.find(id);
    if (found == chunks_.end()) return;
    residentBytes_ -= found->second.bytes;
    arena_->remove(id);
    chunks_.erase(found);
}

bool Renderer::setMultiDraw(bool on) {
    multiDraw_ = on && multiDrawAvailable();
    return multiDraw_;
}

// --- a frame -------------------------------------------------------------------

void Renderer::beginFrame(const View& view) {
    if (view.lights.size() > static_cast<std::size_t>(kMaxLights))
        throw std::invalid_argument("at most " + std::to_string(kMaxLights) + " directional lights, got " +
                                    std::to_string(view.lights.size()));
    if (view.pointLights.size() > static_cast<std::size_t>(kMaxPointLights))
        throw std::invalid_argument("at most " + std::to_string(kMaxPointLights) + " point lights, got " +
                                    std::to_string(view.pointLights.size()));
    finishView();
    GLint bound = 0;
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &bound);
    output_ = static_cast<GLuint>(bound);
    view_ = view;
    viewOpen_ = true;
    if (visibility_) visibility_->beginView(viewsThisFrame_, view.eye, frames_);
    ++viewsThisFrame_;
    sceneDraws_.clear();
    flatDraws_.clear();
    linePoints_.clear();
    cardDraws_.clear();
}

void Renderer::setLighting(const LitUniforms& u, const ShadowUniforms& s, bool shadowed) const {
    glm::vec3 directions[kMaxLights]{};
    glm::vec3 colors[kMaxLights]{};
    const int count = static_cast<int>(view_.lights.size());
    for (int i = 0; i < count; ++i) {
        const DirectionalLight& light = view_.lights[static_cast<std::size_t>(i)];
        const float length = glm::length(light.direction);
        directions[i] = length > 0.0f ? light.direction / length : glm::vec3(0.0f, 1.0f, 0.0f);
        colors[i] = light.color;
    }
    glUniform3fv(u.eye, 1, glm::value_ptr(view_.eye));
    glUniform3fv(u.ambient, 1, glm::value_ptr(view_.ambient));
    glUniform1i(u.lightCount, count);
    glUniform3fv(u.lightDir, kMaxLights, glm::value_ptr(directions[0]));
    glUniform3fv(u.lightColor, kMaxLights, glm::value_ptr(colors[0]));

    glm::vec3 positions[kMaxPointLights]{};
    glm::vec3 pointColors[kMaxPointLights]{};
    float ranges[kMaxPointLights]{};
    const int points = static_cast<int>(view_.pointLights.size());
    for (int i = 0; i < points; ++i) {
        const PointLight& light = view_.pointLights[static_cast<std::size_t>(i)];
        positions[i] = light.position;
        pointColors[i] = light.color;
        ranges[i] = std::max(light.range, 1e-3f);
    }
    glUniform1i(u.pointCount, points);
    glUniform3fv(u.pointPosition, kMaxPointLights, glm::value_ptr(positions[0]));
    glUniform3fv(u.pointColor, kMaxPointLights, glm::value_ptr(pointColors[0]));
    glUniform1fv(u.pointRange, kMaxPointLights, ranges);
    glUniform3fv(u.haze, 1, glm::value_ptr(srgbToLinear(glm::vec3(view_.clearColor))));
    glUniform1f(u.hazeDistance, std::max(view_.hazeDistance, 0.0f));

    glUniform1i(s.enabled, shadowed ? 1 : 0);
    if (shadowed) {
        setMat4(s.matrix, shadow_->worldToTexture());
        glUniform1f(s.offset, 1.5f * shadow_->texelWorld());
        // PCF taps a fixed distance apart on the ground, not a texel: the
        // penumbra stays visible however tight the map's fit.
        const float side = shadow_->texelWorld() * static_cast<float>(shadow_->size());
        glUniform1f(s.texel, std::max(1.0f / static_cast<float>(shadow_->size()), kPenumbraStep / side));
    }
}

bool Renderer::drawChunk(ChunkId id, const glm::mat4& model, const RenderMaterial& material, bool seen) {
    auto found = chunks_.find(id);
    if (found == chunks_.end()) return false;
    const ChunkRecord& c = found->second;
    if (c.indexCount == 0) return true;
    SceneDraw d;
    d.id = id;
    d.model = model;
    d.material = material;
    d.castOnly = !seen;
    sceneDraws_.push_back(d);
    if (!seen) return true;
    stats_.chunksDrawn += 1;
    stats_.trianglesDrawn += c.indexCount / 3;
    return true;
}

void Renderer::drawGround(const GroundStyle& ground) {
    SceneDraw d;
    d.ground = true;
    d.groundStyle = ground;
    sceneDraws_.push_back(d);
    stats_.drawCalls += 1;
    stats_.trianglesDrawn += 2;
}

void Renderer::drawLines(const std::vector<glm::vec3>& points, const glm::vec4& color, LineMode mode,
                         bool depthTested) {
    if (points.size() < 2) return;
    FlatDraw d;
    d.primitive = mode == LineMode::Segments ? GL_LINES : mode == LineMode::Strip ? GL_LINE_STRIP : GL_LINE_LOOP;
    d.first = static_cast<GLsizei>(linePoints_.size());
    d.count = static_cast<GLsizei>(points.size());
    d.color = color;
    d.depthTested = depthTested;
    linePoints_.insert(linePoints_.end(), points.begin(), points.end());
    flatDraws_.push_back(d);
    stats_.drawCalls += 1;
}

void Renderer::drawSphere(const glm::vec3& center, float radius, const glm::vec4& color, bool wireframe) {
    if (!(radius > 0.0f)) return;
    if (!wireframe) {
        FlatDraw d;
        d.primitive = GL_TRIANGLES;
        d.sphere = true;
        d.count = sphereIndexCount_;
        d.model = glm::scale(glm::translate(glm::mat4(1.0f), center), glm::vec3(radius));
        d.color = color;
        flatDraws_.push_back(d);
        stats_.drawCalls += 1;
        stats_.trianglesDrawn += static_cast<std::size_t>(sphereIndexCount_ / 3);
        return;
    }
    const glm::vec3 x(1, 0, 0), y(0, 1, 0), z(0, 0, 1);
    drawLines(circlePoints(center, radius, x, y, kCircleSegments), color, LineMode::Loop);
    drawLines(circlePoints(center, radius, y, z, kCircleSegments), color, LineMode::Loop);
    drawLines(circlePoints(center, radius, z, x, kCircleSegments), color, LineMode::Loop);
    // The outline seen from the eye: the circle where the view cone touches
    // the sphere, nearer the eye than the centre and a little smaller.
    const glm::vec3 toEye = view_.eye - center;
    const float d = glm::length(toEye);
    if (d > radius) {
        const glm::vec3 w = toEye / d;
        const glm::vec3 helper = std::fabs(w.y) < 0.9f ? y : x;
        const glm::vec3 u = glm::normalize(glm::cross(helper, w));
        const glm::vec3 v = glm::cross(w, u);
        const float offset = radius * radius / d;
        const float r = std::sqrt(radius * radius - offset * offset);
        drawLines(circlePoints(center + offset * w, r, u, v, kCircleSegments), color, LineMode::Loop);
    }
}

// --- rendering a recorded view ------------------------------------------------

void Renderer::gatherChunks(const RenderQuality& q, glm::vec3& lo, glm::vec3& hi) {
    for (auto& batch : batches_) batch->clear();
    shadowBatch_->clear();
    lo = glm::vec3(1e30f);
    hi = glm::vec3(-1e30f);
    const float shadowReach = q.shadowDistance > 0.0f ? q.shadowDistance : 1e30f;
    // Draws of one placement come together (a sculpture's chunks): they
    // share one record, made when the placement or material changes.
    const auto kindOf = [](const SceneDraw& d) { return static_cast<std::size_t>(surfaceKindIndex(d.material.kind)); };
    const SceneDraw* previous = nullptr;
    bool previousNormals = false;
    DrawRecord current{};
    std::size_t record = 0, shadowRecord = 0;
    bool recordMade = false, shadowRecordMade = false;
    float stretch = 1.0f;  // the model matrix's largest scale, for chunk radii
    for (const SceneDraw& d : sceneDraws_) {
        if (d.ground) continue;
        auto found = chunks_.find(d.id);
        const ArenaSlot* slot = arena_->slot(d.id);
        if (found == chunks_.end() || slot == nullptr) continue;  // dropped or emptied since recorded
        const ChunkRecord& c = found->second;
        const bool same = previous && previousNormals == c.hasNormals && previous->model == d.model &&
                          previous->material == d.material;
        if (!same) {
            current = drawRecord(d.model, d.material, c.hasNormals);
            recordMade = shadowRecordMade = false;
            stretch = std::max({glm::length(glm::vec3(d.model[0])), glm::length(glm::vec3(d.model[1])),
                                glm::length(glm::vec3(d.model[2]))});
            previous = &d;
            previousNormals = c.hasNormals;
        }
        if (!d.castOnly) {
            if (!recordMade) {
                record = batches_[kindOf(d)]->addRecord(current);
                recordMade = true;
            }
            batches_[kindOf(d)]->add(*slot, record);
        }
        // A caster when it comes within the shadow's reach of the eye; the
        // map is fitted to the casters' bounding spheres.
        const glm::vec3 centre = glm::vec3(d.model * glm::vec4(0.5f * (c.lo + c.hi), 1.0f));
        const float radius = 0.5f * glm::length(c.hi - c.lo) * stretch;
        if (glm::length(centre - view_.eye) - radius > shadowReach) continue;
        if (!shadowRecordMade) {
            shadowRecord = shadowBatch_->addRecord(current);
            shadowRecordMade = true;
        }
        shadowBatch_->add(*slot, shadowRecord);
        lo = glm::min(lo, centre - glm::vec3(radius));
        hi = glm::max(hi, centre + glm::vec3(radius));
    }
    // Cards cast too (facing the sun), fitted by their bounding spheres.
    cardsCast_ = false;
    for (const ImpostorCard& card : cardDraws_) {
        const glm::vec3 centre = glm::vec3(card.model * glm::vec4(glm::vec3(card.sphere), 1.0f));
        const float radius = card.sphere.w * glm::length(glm::vec3(card.model[0]));
        if (glm::length(centre - view_.eye) - radius > shadowReach) continue;
        cardsCast_ = true;
        lo = glm::min(lo, centre - glm::vec3(radius));
        hi = glm::max(hi, centre + glm::vec3(radius));
    }
}

bool Renderer::renderShadows(const RenderQuality& q, const glm::vec3& lo, const glm::vec3& hi) {
    // The ground only receives: the casters are the view's chunks.
    if (!q.shadows || view_.lights.empty() || (shadowBatch_->empty() && !cardsCast_)) return false;
    ShadowInputs inputs{lo, hi, view_.lights.front().direction, q.shadowMapSize, arena_->generation(),
                        atlas_ ? atlas_->bakes() : 0};
    if (shadowReuse_ && shadowHolds_ && *shadowHolds_ == inputs && shadowBatch_->drawsTheSameAs(*shadowHeldCasters_) &&
        sameCards(cardDraws_, shadowHeldCards_)) {
        stats_.shadowMapsKept += 1;
        return true;
    }
    timers_->begin(GpuPass::Shadow);
    stats_.shadowDrawCalls += shadow_->render(*shadowBatch_, *arena_, multiDraw_, lo, hi,
                                              view_.lights.front().direction, q.shadowMapSize);
    if (!cardDraws_.empty()) {
        glDisable(GL_CULL_FACE);
        stats_.shadowDrawCalls +=
            cards_->drawShadows(*atlas_, shadow_->lightViewProjection(), view_.lights.front().direction);
        glEnable(GL_CULL_FACE);
    }
    timers_->end();
    stats_.shadowMapsDrawn += 1;
    if (!shadowHeldCasters_) shadowHeldCasters_ = std::make_unique<ChunkBatch>();
    shadowHeldCasters_->copyDrawsOf(*shadowBatch_);
    shadowHeldCards_ = cardDraws_;
    shadowHolds_ = inputs;
    return true;
}

void Renderer::setSkyBaked(bool on) { sky_->setBaked(on); }

bool Renderer::skyBaked() const { return sky_->baked(); }

void Renderer::renderScene(const RenderQuality& q, bool shadowed) {
    timers_->begin(GpuPass::Scene);
    glBindFramebuffer(GL_FRAMEBUFFER, targets_->framebuffer());
    glViewport(0, 0, targets_->size().x, targets_->size().y);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_BLEND);
    // (At one sample the targets are plain textures, so this changes
    // nothing there: render_targets.h.)
    glEnable(GL_MULTISAMPLE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glFrontFace(GL_CCW);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    // Alpha 0: nothing of the sky is for occlusion to dim.
    const glm::vec3 sky = srgbToLinear(glm::vec3(view_.clearColor));
    glClearColor(sky.r, sky.g, sky.b, 0.0f);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    glActiveTexture(GL_TEXTURE0 + kShadowUnit);
    glBindTexture(GL_TEXTURE_2D, shadowed ? shadow_->texture() : 0);
    glActiveTexture(GL_TEXTURE0);
    const glm::mat4 viewProjection = view_.projection * view_.view;
    groundProgram_.use();
    setMat4(ground_.viewProjection, viewProjection);
    setLighting(groundLit_, groundShadow_, shadowed);

    // Sculptures before the ground: they hide much of it, and early depth
    // tests then skip its pixels.
    for (int kind = 0; kind < kSurfaceKindCount; ++kind) {
        ChunkBatch& batch = *batches_[static_cast<std::size_t>(kind)];
        if (batch.empty()) continue;
        MeshProgram& m = meshProgram(kind);
        m.program.use();
        setMat4(m.viewProjection, viewProjection);
        glUniform1f(m.bump, q.materialBump ? 1.0f : 0.0f);
        setLighting(m.lit, m.shadow, shadowed);
        stats_.drawCalls += batch.draw(*arena_, multiDraw_);
    }
    if (!cardDraws_.empty()) {
        cards_->sceneProgram().use();
        setLighting(cardLit_, cardShadow_, shadowed);
        stats_.drawCalls += cards_->drawScene(*atlas_, viewProjection, view_.eye);
    }
    for (const SceneDraw& d : sceneDraws_)
        if (d.ground) drawGroundNow(d.groundStyle);
    const std::size_t skyBakes = sky_->bakes();
    sky_->draw(view_, q.skyMapSize);
    stats_.skyBakes += sky_->bakes() - skyBakes;
    // Every box against the finished depth (sky included: it writes none).
    if (visibility_) stats_.visibilityTests += visibility_->issue(viewProjection);
    timers_->end();
}

OcclusionImage Renderer::drawPicture(const RenderQuality& q) {
    // The scene at the render scale; the composite scales it to the output.
    const glm::ivec2 sceneSize(scenePixels(view_.viewport.x, q), scenePixels(view_.viewport.y, q));
    targets_->ensure(sceneSize, q.msaaSamples);

    glm::vec3 lo, hi;
    if (!cardDraws_.empty()) cards_->send(cardDraws_);
    gatherChunks(q, lo, hi);
    const bool shadowed = renderShadows(q, lo, hi);
    renderScene(q, shadowed);
    OcclusionImage occlusion;
    if (q.ambientOcclusion) {
        timers_->begin(GpuPass::Occlusion);
        occlusion = occlusion_->render(*targets_, view_.projection, q);
        timers_->end();
    }
    return occlusion;
}

void Renderer::finishView() {
    if (!viewOpen_) return;
    viewOpen_ = false;
    const PictureStep step = still_->step(pictureReuse_ && holdsThisView(), quality_, stillQualities_);
    const bool kept = step.kind == PictureStep::Keep, measured = step.kind == PictureStep::Draw;
    (measured ? viewsMeasured_ : viewsNotMeasured_) += 1;
    OcclusionImage occlusion;
    RenderQuality shown = quality_;
    if (kept) {
        stats_.picturesKept += 1;
        occlusion = still_->occlusion();
        shown = still_->quality();
        // What the scene pass would have set (panels drawn since may have changed it).
        glDisable(GL_SCISSOR_TEST);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
        testVisibilityOverTheHeldPicture();
    } else {
        // A sharpened view's time is not what the automatic quality should
        // judge the moving one by: measured, then dropped.
        timers_->nextView(measured);
        if (step.kind == PictureStep::Sharpen) {
            shown = stillQualities_[step.still];
            stats_.picturesSharpened += 1;
        }
        occlusion = drawPicture(shown);
        if (pictureReuse_) still_->drawn(shown, occlusion);
        timers_->begin(GpuPass::Post);
    }
    writeOutput(kept, occlusion, shown);
    drawOverTheOutput();
    timers_->end();
    if (pictureReuse_ && !kept) holdThisView();
}

void Renderer::testVisibilityOverTheHeldPicture() {
    if (!visibility_) return;
    glBindFramebuffer(GL_FRAMEBUFFER, targets_->framebuffer());
    glViewport(0, 0, targets_->size().x, targets_->size().y);
    stats_.visibilityTests += visibility_->issue(view_.projection * view_.view);
}

void Renderer::writeOutput(bool kept, const OcclusionImage& occlusion, const RenderQuality& shown) {
    glBindFramebuffer(GL_FRAMEBUFFER, output_);
    glViewport(0, 0, view_.viewport.x, view_.viewport.y);
    if (!kept) {
        if (heldOutput_) heldOutput_->forget();
        post_->composite(*targets_, occlusion, shown.exposure, view_.viewport, shown.smoothUpscale);
        return;
    }
    // Composited once into the held output, then copied from there.
    if (!heldOutput_) heldOutput_ = std::make_unique<HeldOutput>();
    if (!heldOutput_->holds(view_.viewport)) {
        heldOutput_->bindForWriting(view_.viewport);
        post_->composite(*targets_, occlusion, shown.exposure, view_.viewport, shown.smoothUpscale);
        glBindFramebuffer(GL_FRAMEBUFFER, output_);
        glViewport(0, 0, view_.viewport.x, view_.viewport.y);
    }
    heldOutput_->copyOut();
}

void Renderer::drawOverTheOutput() {
    if (!flatDraws_.empty()) {
        flatProgram_.use();
        setMat4(flat_.view, view_.view);
        setMat4(flat_.projection, view_.projection);
        glBindBuffer(GL_ARRAY_BUFFER, streamVbo_.get());
        // Orphan and refill: the previous view's points may still be in flight.
        glBufferData(GL_ARRAY_BUFFER, byteSize(linePoints_), linePoints_.data(), GL_STREAM_DRAW);
        glBindBuffer(GL_ARRAY_BUFFER, 0);
        for (const FlatDraw& d : flatDraws_) drawFlatNow(d);
    }
    if (std::any_of(sceneDraws_.begin(), sceneDraws_.end(), [](const SceneDraw& d) { return d.material.edges != 0; }))
        drawEdges();
}

namespace {

bool sameLights(const std::vector<DirectionalLight>& a, const std::vector<DirectionalLight>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i].direction != b[i].direction || a[i].color != b[i].color) return false;
    return true;
}

bool samePoints(const std::vector<PointLight>& a, const std::vector<PointLight>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (a[i].position != b[i].position || a[i].color != b[i].color || a[i].range != b[i].range) return false;
    return true;
}

// The view's lights, camera, viewport and sky, compared exactly.
bool sameView(const View& a, const View& b) {
    return a.view == b.view && a.projection == b.projection && a.eye == b.eye && a.viewport == b.viewport &&
           a.clearColor == b.clearColor && a.ambient == b.ambient && a.hazeDistance == b.hazeDistance &&
           a.clouds == b.clouds && sameLights(a.lights, b.lights) && samePoints(a.pointLights, b.pointLights);
}

bool sameGround(const GroundStyle& a, const GroundStyle& b) {
    return a.color == b.color && a.lineColor == b.lineColor && a.spacing == b.spacing &&
           a.majorEvery == b.majorEvery && a.lineWidth == b.lineWidth && a.halfExtent == b.halfExtent &&
           a.gardenHalfExtent == b.gardenHalfExtent && a.gridReach == b.gridReach && a.stripeWidth == b.stripeWidth;
}

}  // namespace

bool Renderer::holdsThisView() const {
    if (!still_->holds() || held_.output != output_ || held_.arena != arena_->generation() ||
        held_.bakes != (atlas_ ? atlas_->bakes() : 0) || held_.skyBaked != sky_->baked() ||
        !sameView(held_.view, view_) || held_.draws.size() != sceneDraws_.size() || !sameCards(cardDraws_, held_.cards))
        return false;
    for (std::size_t i = 0; i < sceneDraws_.size(); ++i) {
        const SceneDraw& a = sceneDraws_[i];
        const SceneDraw& b = held_.draws[i];
        if (a.ground != b.ground || a.castOnly != b.castOnly || a.id != b.id || a.model != b.model ||
            !(a.material == b.material) || (a.ground && !sameGround(a.groundStyle, b.groundStyle)))
            return false;
    }
    return true;
}

void Renderer::holdThisView() {
    held_.view = view_;
    held_.output = output_;
    // Taken, not copied: the open view is finished and beginFrame clears them.
    std::swap(held_.draws, sceneDraws_);
    held_.cards = cardDraws_;
    held_.arena = arena_->generation();
    held_.bakes = atlas_ ? atlas_->bakes() : 0;
    held_.skyBaked = sky_->baked();
}

void Renderer::setPictureReuse(bool on) {
    pictureReuse_ = on;
    if (!on) {
        still_->forget();
        held_.draws.clear();
        held_.cards.clear();
    }
}

void Renderer::drawEdges() {
    // The front faces' edges, pulled towards the eye like the other lines,
    // blended so the surface shows through: one call per chunk (a view for
    // judging the mesh, not for speed).
    flatProgram_.use();
    setMat4(flat_.view, view_.view);
    setMat4(flat_.projection, view_.projection);
    glUniform4fv(flat_.color, 1, glm::value_ptr(kEdgeColor));
    glEnable(GL_BLEND);
    glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    glDepthMask(GL_FALSE);
    glEnable(GL_DEPTH_TEST);
    glEnable(GL_CULL_FACE);  // back faces' edges stay hidden
    glPolygonMode(GL_FRONT_AND_BACK, GL_LINE);
    for (const SceneDraw& d : sceneDraws_) {
        if (d.ground || d.castOnly || d.material.edges == 0) continue;
        const ArenaSlot* slot = arena_->slot(d.id);
        if (slot == nullptr) continue;
        glBindVertexArray(arena_->vertexArray(slot->page));
        setMat4(flat_.model, d.model);
        glDrawElementsBaseVertex(GL_TRIANGLES, static_cast<GLsizei>(slot->indexCount), GL_UNSIGNED_INT,
                                 byteOffset(slot->firstIndex * sizeof(std::uint32_t)),
                                 static_cast<GLint>(slot->firstVertex));
    }
    glBindVertexArray(0);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
}

void Renderer::drawGroundNow(const GroundStyle& ground) {
    const float h = ground.halfExtent;
    // Two triangles counter-clockwise seen from above (+y), so culling
    // hides the plane from below.
    const float corners[6][3] = {{-h, 0, -h}, {-h, 0, h}, {h, 0, h}, {-h, 0, -h}, {h, 0, h}, {h, 0, -h}};
    glBindBuffer(GL_ARRAY_BUFFER, groundVbo_.get());
    glBufferSubData(GL_ARRAY_BUFFER, 0, sizeof corners, corners);
    glBindBuffer(GL_ARRAY_BUFFER, 0);

    groundProgram_.use();
    glUniform3fv(ground_.groundColor, 1, glm::value_ptr(ground.color));
    glUniform3fv(ground_.lineColor, 1, glm::value_ptr(ground.lineColor));
    glUniform1f(ground_.spacing, ground.spacing > 0.0f ? ground.spacing : 1.0f);
    glUniform1f(ground_.lineWidth, ground.lineWidth);
    glUniform1i(ground_.majorEvery, ground.majorEvery);
    glUniform2fv(ground_.gardenHalfExtent, 1, glm::value_ptr(ground.gardenHalfExtent));
    glUniform1f(ground_.gridReach, ground.gridReach);
    glUniform1f(ground_.stripeWidth, ground.stripeWidth);
    // Pushed back by its own depth slope: lines lying on the ground (the
    // morph triangle) and sculpture bases win against it even at grazing
    // angles, where a pixel spans centimetres of depth.
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(kGroundOffsetFactor, kGroundOffsetUnits);
    glBindVertexArray(groundVao_.get());
    glDrawArrays(GL_TRIANGLES, 0, 6);
    glBindVertexArray(0);
    glDisable(GL_POLYGON_OFFSET_FILL);
}

void Renderer::drawFlatNow(const FlatDraw& d) {
    setMat4(flat_.model, d.model);
    glUniform4fv(flat_.color, 1, glm::value_ptr(d.color));
    const bool blend = d.color.a < 1.0f;
    if (blend) {
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glDepthMask(GL_FALSE);  // a translucent shell must not hide what is behind it
    }
    if (!d.depthTested) glDisable(GL_DEPTH_TEST);
    if (d.sphere) {
        glBindVertexArray(sphereVao_.get());
        glDrawElements(d.primitive, d.count, GL_UNSIGNED_INT, byteOffset(0));
    } else {
        glBindVertexArray(streamVao_.get());
        glDrawArrays(d.primitive, d.first, d.count);
    }
    glBindVertexArray(0);
    if (!d.depthTested) glEnable(GL_DEPTH_TEST);
    if (blend) {
        glDisable(GL_BLEND);
        glDepthMask(GL_TRUE);
    }
}

void Renderer::setOcclusionCulling(bool on) {
    occlusionCulling_ = on;
    if (!on && visibility_) visibility_->clear();
}

bool Renderer::wasHidden(std::uint64_t key, const glm::vec3& worldLo, const glm::vec3& worldHi) {
    if (!occlusionCulling_ || !visibility_) return false;
    const bool hidden = visibility_->hidden(key, worldLo, worldHi);
    stats_.sculpturesHidden += hidden ? 1 : 0;
    return hidden;
}

void Renderer::testVisibility(std::uint64_t key, const glm::vec3& worldLo, const glm::vec3& worldHi) {
    if (!occlusionCulling_ || !viewOpen_) return;
    if (!visibility_) {
        visibility_ = std::make_unique<VisibilityQueries>();
        visibility_->beginView(viewsThisFrame_ - 1, view_.eye, frames_);
    }
    visibility_->test(key, worldLo, worldHi, view_.projection * view_.view);
}

void Renderer::forgetHiddenBehind(const glm::vec3& worldLo, const glm::vec3& worldHi) {
    if (visibility_) visibility_->forgetBehind(worldLo, worldHi);
}

RenderStats Renderer::endFrame() {
    finishView();
    if (atlas_) atlas_->nextFrame();
    viewsThisFrame_ = 0;
    ++frames_;
    RenderStats done = stats_;
    const auto& ms = timers_->latest();
    done.gpuShadowMs = ms[static_cast<std::size_t>(GpuPass::Shadow)];
    done.gpuSceneMs = ms[static_cast<std::size_t>(GpuPass::Scene)];
    done.gpuOcclusionMs = ms[static_cast<std::size_t>(GpuPass::Occlusion)];
    done.gpuPostMs = ms[static_cast<std::size_t>(GpuPass::Post)];
    // A frame of held or sharpened views only: no time of the quality set.
    if (viewsMeasured_ == 0 && viewsNotMeasured_ > 0)
        done.gpuShadowMs = done.gpuSceneMs = done.gpuOcclusionMs = done.gpuPostMs = -1.0f;
    viewsMeasured_ = viewsNotMeasured_ = 0;
    stats_ = RenderStats{};
    return done;
}

}  // namespace hg::garden
