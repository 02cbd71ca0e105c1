#include "garden/render/renderer.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "garden/render/shaders.h"
#include "garden/render/shapes.h"

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

}  // namespace

Renderer::Renderer()
    : meshProgram_("mesh", shaders::kMeshVertex, shaders::kMeshFragment),
      groundProgram_("ground", shaders::kGroundVertex, shaders::kGroundFragment),
      flatProgram_("flat", shaders::kFlatVertex, shaders::kFlatFragment) {
    auto lit = [](const ShaderProgram& p) {
        return LitUniforms{p.uniform("uEye"),         p.uniform("uAmbient"),       p.uniform("uLightCount"),
                           p.uniform("uLightDir"),    p.uniform("uLightColor"),    p.uniform("uPointCount"),
                           p.uniform("uPointPosition"), p.uniform("uPointColor"), p.uniform("uPointRange")};
    };
    meshLit_ = lit(meshProgram_);
    groundLit_ = lit(groundProgram_);
    const ShaderProgram& m = meshProgram_;
    mesh_ = {m.uniform("uModel"),     m.uniform("uNormalMatrix"), m.uniform("uViewProjection"),
             m.uniform("uBaseColor"), m.uniform("uSpecular"),     m.uniform("uShininess"),
             m.uniform("uHasNormals")};
    const ShaderProgram& g = groundProgram_;
    ground_ = {g.uniform("uViewProjection"), g.uniform("uGroundColor"), g.uniform("uLineColor"),
               g.uniform("uSpacing"),        g.uniform("uLineWidth"),   g.uniform("uMajorEvery")};
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

// --- chunk buffers -----------------------------------------------------------

std::size_t Renderer::upload(ChunkId id, std::uint64_t version, const poly::Mesh& mesh) {
    auto found = chunks_.find(id);
    if (found != chunks_.end() && found->second.version == version) return 0;
    checkMesh(mesh);

    ChunkBuffers& c = chunks_[id];
    residentBytes_ -= c.bytes;
    c.version = version;
    c.indexCount = static_cast<GLsizei>(mesh.indices.size());
    c.hasNormals = !mesh.normals.empty();
    c.bytes = 0;
    if (mesh.empty()) {
        // Keep the record (the chunk is current and empty), free the memory.
        c.vao.reset();
        c.vertices.reset();
        c.indices.reset();
        return 0;
    }
    if (!c.vao) {
        c.vao = gl::VertexArray::create();
        c.vertices = gl::Buffer::create();
        c.indices = gl::Buffer::create();
    }
    const GLsizeiptr positionBytes = byteSize(mesh.positions);
    const GLsizeiptr normalBytes = byteSize(mesh.normals);
    const GLsizeiptr indexBytes = byteSize(mesh.indices);

    glBindVertexArray(c.vao.get());
    glBindBuffer(GL_ARRAY_BUFFER, c.vertices.get());
    // Fresh storage each version: the driver need not wait for draws still
    // reading the old contents.
    glBufferData(GL_ARRAY_BUFFER, positionBytes + normalBytes, nullptr, GL_STATIC_DRAW);
    glBufferSubData(GL_ARRAY_BUFFER, 0, positionBytes, mesh.positions.data());
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float), byteOffset(0));
    if (c.hasNormals) {
        glBufferSubData(GL_ARRAY_BUFFER, positionBytes, normalBytes, mesh.normals.data());
        glEnableVertexAttribArray(1);
        glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 3 * sizeof(float),
                              byteOffset(static_cast<std::size_t>(positionBytes)));
    } else {
        glDisableVertexAttribArray(1);
    }
    glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, c.indices.get());
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, indexBytes, mesh.indices.data(), GL_STATIC_DRAW);
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);

    c.bytes = static_cast<std::size_t>(positionBytes + normalBytes + indexBytes);
    residentBytes_ += c.bytes;
    stats_.bytesUploaded += c.bytes;
    return c.bytes;
}

bool Renderer::has(ChunkId id, std::uint64_t version) const {
    auto found = chunks_.find(id);
    return found != chunks_.end() && found->second.version == version;
}

bool Renderer::has(ChunkId id) const { return chunks_.count(id) != 0; }

void Renderer::drop(ChunkId id) {
    auto found = chunks_.find(id);
    if (found == chunks_.end()) return;
    residentBytes_ -= found->second.bytes;
    chunks_.erase(found);
}

// --- a frame -------------------------------------------------------------------

void Renderer::beginFrame(const View& view) {
    if (view.lights.size() > static_cast<std::size_t>(kMaxLights))
        throw std::invalid_argument("at most " + std::to_string(kMaxLights) + " directional lights, got " +
                                    std::to_string(view.lights.size()));
    if (view.pointLights.size() > static_cast<std::size_t>(kMaxPointLights))
        throw std::invalid_argument("at most " + std::to_string(kMaxPointLights) + " point lights, got " +
                                    std::to_string(view.pointLights.size()));
    view_ = view;

    glViewport(0, 0, view.viewport.x, view.viewport.y);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_BLEND);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glDepthMask(GL_TRUE);
    glEnable(GL_CULL_FACE);
    glCullFace(GL_BACK);
    glFrontFace(GL_CCW);
    glPolygonMode(GL_FRONT_AND_BACK, GL_FILL);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glClearColor(view.clearColor.r, view.clearColor.g, view.clearColor.b, view.clearColor.a);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    const glm::mat4 viewProjection = view.projection * view.view;
    meshProgram_.use();
    setMat4(mesh_.viewProjection, viewProjection);
    setLighting(meshLit_);
    groundProgram_.use();
    setMat4(ground_.viewProjection, viewProjection);
    setLighting(groundLit_);
    flatProgram_.use();
    setMat4(flat_.view, view.view);
    setMat4(flat_.projection, view.projection);
}

void Renderer::setLighting(const LitUniforms& u) const {
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
}

bool Renderer::drawChunk(ChunkId id, const glm::mat4& model, const RenderMaterial& material) {
    auto found = chunks_.find(id);
    if (found == chunks_.end()) return false;
    const ChunkBuffers& c = found->second;
    if (c.indexCount == 0) return true;

    meshProgram_.use();
    setMat4(mesh_.model, model);
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(model)));
    glUniformMatrix3fv(mesh_.normalMatrix, 1, GL_FALSE, glm::value_ptr(normalMatrix));
    glUniform3fv(mesh_.baseColor, 1, glm::value_ptr(material.baseColor));
    glUniform1f(mesh_.specular, material.specular);
    glUniform1f(mesh_.shininess, material.shininess);
    glUniform1i(mesh_.hasNormals, c.hasNormals ? 1 : 0);
    glBindVertexArray(c.vao.get());
    glDrawElements(GL_TRIANGLES, c.indexCount, GL_UNSIGNED_INT, byteOffset(0));
    glBindVertexArray(0);

    stats_.drawCalls += 1;
    stats_.trianglesDrawn += static_cast<std::size_t>(c.indexCount / 3);
    return true;
}

void Renderer::drawGround(const GroundStyle& ground) {
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
    // Pushed back by its own depth slope: lines lying on the ground (the
    // morph triangle) and sculpture bases win against it even at grazing
    // angles, where a pixel spans centimetres of depth.
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(kGroundOffsetFactor, kGroundOffsetUnits);
    glBindVertexArray(groundVao_.get());
    glDrawArrays(GL_TRIANGLES, 0, 6);
    glBindVertexArray(0);
    glDisable(GL_POLYGON_OFFSET_FILL);
    stats_.drawCalls += 1;
    stats_.trianglesDrawn += 2;
}

void Renderer::drawFlat(GLenum primitive, GLuint vao, GLsizei count, bool indexed, const glm::mat4& model,
                        const glm::vec4& color, bool depthTested) {
    flatProgram_.use();
    setMat4(flat_.model, model);
    glUniform4fv(flat_.color, 1, glm::value_ptr(color));
    const bool blend = color.a < 1.0f;
    if (blend) {
        glEnable(GL_BLEND);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glDepthMask(GL_FALSE);  // a translucent shell must not hide what is behind it
    }
    if (!depthTested) glDisable(GL_DEPTH_TEST);
    glBindVertexArray(vao);
    if (indexed)
        glDrawElements(primitive, count, GL_UNSIGNED_INT, byteOffset(0));
    else
        glDrawArrays(primitive, 0, count);
    glBindVertexArray(0);
    if (!depthTested) glEnable(GL_DEPTH_TEST);
    if (blend) {
        glDisable(GL_BLEND);
        glDepthMask(GL_TRUE);
    }
    stats_.drawCalls += 1;
}

void Renderer::drawLines(const std::vector<glm::vec3>& points, const glm::vec4& color, LineMode mode,
                         bool depthTested) {
    if (points.size() < 2) return;
    glBindBuffer(GL_ARRAY_BUFFER, streamVbo_.get());
    // Orphan and refill: the previous call's points may still be in flight.
    glBufferData(GL_ARRAY_BUFFER, byteSize(points), points.data(), GL_STREAM_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
    const GLenum primitive = mode == LineMode::Segments ? GL_LINES : mode == LineMode::Strip ? GL_LINE_STRIP : GL_LINE_LOOP;
    drawFlat(primitive, streamVao_.get(), static_cast<GLsizei>(points.size()), false, glm::mat4(1.0f), color,
             depthTested);
}

void Renderer::drawSphere(const glm::vec3& center, float radius, const glm::vec4& color, bool wireframe) {
    if (!(radius > 0.0f)) return;
    if (!wireframe) {
        const glm::mat4 model = glm::scale(glm::translate(glm::mat4(1.0f), center), glm::vec3(radius));
        drawFlat(GL_TRIANGLES, sphereVao_.get(), sphereIndexCount_, true, model, color, true);
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

RenderStats Renderer::endFrame() {
    RenderStats done = stats_;
    stats_ = RenderStats{};
    return done;
}

}  // namespace hg::garden
