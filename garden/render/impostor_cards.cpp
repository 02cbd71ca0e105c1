#include "garden/render/impostor_cards.h"

#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <string>

#include "garden/render/impostor_atlas.h"
#include "garden/render/shaders.h"

namespace hg::garden {
namespace {

const char* const kCardVertex = R"(#version 330 core
layout(location = 0) in vec2 aCorner;  // -1..1
layout(location = 1) in vec4 iModel0;
layout(location = 2) in vec4 iModel1;
layout(location = 3) in vec4 iModel2;
layout(location = 4) in vec4 iModel3;
layout(location = 5) in vec4 iSphere;  // model-space centre, radius
layout(location = 6) in vec4 iLook;    // layer, specular, shininess, metallic
uniform mat4 uViewProjection;
uniform vec3 uFrom;      // the eye (world); with uParallel, the direction towards the light
uniform bool uParallel;  // the sun's parallel rays (the shadow map)
out vec3 vPoint;         // the card's point, model space
flat out vec3 vToViewer; // model space, unit: from the centre towards the eye (or the light)
flat out vec3 vEye;      // the eye, model space
flat out mat4 vModel;
flat out vec4 vSphere;
flat out vec4 vLook;
void main() {
    mat4 model = mat4(iModel0, iModel1, iModel2, iModel3);
    vec3 c = (model * vec4(iSphere.xyz, 1.0)).xyz;
    float r = iSphere.w * length(model[0].xyz);
    vec3 w = uParallel ? uFrom : uFrom - c;
    float dist = max(length(w), 1e-6);
    w /= dist;
    // Seen in perspective, a sphere's outline is a little wider than its radius.
    float widen = uParallel ? 1.0 : min(dist / sqrt(max(dist * dist - r * r, 0.0625 * dist * dist)), 4.0);
    vec3 up0 = abs(w.y) > 0.999 ? vec3(0.0, 0.0, -1.0) : vec3(0.0, 1.0, 0.0);
    vec3 right = normalize(cross(up0, w)), up = cross(w, right);
    vec3 corner = c + (right * aCorner.x + up * aCorner.y) * (r * widen * 1.02);
    mat4 toModel = inverse(model);
    vPoint = (toModel * vec4(corner, 1.0)).xyz;
    vEye = (toModel * vec4(uFrom, 1.0)).xyz;
    vToViewer = uParallel ? normalize(mat3(toModel) * w) : normalize(vEye - iSphere.xyz);
    vModel = model;
    vSphere = iSphere;
    vLook = iLook;
    gl_Position = uViewProjection * vec4(corner, 1.0);
}
)";

// Sampling the atlas along a ray: the four frames nearest the direction the
// card is seen from, each read where the ray meets its plane.
const char* const kSampleGlsl = R"(
in vec3 vPoint;
flat in vec3 vToViewer;
flat in vec3 vEye;
flat in mat4 vModel;
flat in vec4 vSphere;
flat in vec4 vLook;
uniform sampler2DArray uImpostorAlbedo;       // premultiplied colour, coverage
uniform sampler2DArray uImpostorNormalDepth;  // premultiplied normal, depth (reaches)
uniform int uViews;
uniform float uReach;         // a frame's half-width in sphere radii
uniform float uFramePixels;
// The same formulas as ImpostorAtlas::frameDirection and frameViewProjection.
vec3 octDecode(vec2 uv) {
    vec2 ab = uv * 2.0 - 1.0;
    vec2 p = 0.5 * vec2(ab.x + ab.y, ab.x - ab.y);
    return normalize(vec3(p.x, 1.0 - abs(p.x) - abs(p.y), p.y));
}
vec2 octEncode(vec3 d) {
    d.y = max(d.y, 0.0);  // from below the horizon: the horizon's frames
    d /= abs(d.x) + abs(d.y) + abs(d.z);
    return vec2(d.x + d.z, d.x - d.z) * 0.5 + 0.5;
}
void frameBasis(vec3 d, out vec3 r, out vec3 u) {
    vec3 up0 = abs(d.y) > 0.999 ? vec3(0.0, 0.0, -1.0) : vec3(0.0, 1.0, 0.0);
    r = normalize(cross(up0, d));
    u = cross(d, r);
}
vec4 gAlbedo;
vec3 gNormal;
vec3 gPoint;
float gLod;
void addFrame(ivec2 f, float weight, vec3 o, vec3 dir) {
    vec3 d = octDecode(vec2(f) / float(uViews - 1));
    float facing = dot(dir, d);
    if (weight <= 0.0 || facing > -1e-3) return;
    vec3 r, u;
    frameBasis(d, r, u);
    vec3 c = vSphere.xyz;
    float reach = vSphere.w * uReach;
    vec3 q = o + dir * (dot(c - o, d) / facing) - c;
    vec2 local = vec2(dot(q, r), dot(q, u)) / reach;
    if (abs(local.x) >= 1.0 || abs(local.y) >= 1.0) return;
    vec3 uvw = vec3((vec2(f) + 0.5 + 0.5 * local) / float(uViews), vLook.x);
    vec4 a = textureLod(uImpostorAlbedo, uvw, gLod);
    vec4 nd = textureLod(uImpostorNormalDepth, uvw, gLod);
    gAlbedo += weight * a;
    gNormal += weight * nd.xyz;
    gPoint += weight * (a.a * (c + q) + d * (nd.w * reach));
}
// The coverage (0..1) of the ray (o, dir) through the impostor, and its
// colour, model-space normal and point where it is covered.
float sampleImpostor(vec3 o, vec3 dir, out vec3 base, out vec3 normal, out vec3 point) {
    // The level of detail from the card's size on screen, before any branch.
    gLod = max(log2(length(fwidth(vPoint)) * uFramePixels / (2.0 * vSphere.w * uReach) + 1e-9), 0.0);
    vec2 g = octEncode(vToViewer) * float(uViews - 1);
    ivec2 f0 = ivec2(min(floor(g), vec2(float(uViews - 2))));
    vec2 t = g - vec2(f0);
    gAlbedo = vec4(0.0);
    gNormal = vec3(0.0);
    gPoint = vec3(0.0);
    addFrame(f0, (1.0 - t.x) * (1.0 - t.y), o, dir);
    addFrame(f0 + ivec2(1, 0), t.x * (1.0 - t.y), o, dir);
    addFrame(f0 + ivec2(0, 1), (1.0 - t.x) * t.y, o, dir);
    addFrame(f0 + ivec2(1, 1), t.x * t.y, o, dir);
    float covered = max(gAlbedo.a, 1e-4);
    base = gAlbedo.rgb / covered;
    normal = length(gNormal) > 1e-6 ? normalize(gNormal) : vToViewer;
    point = gAlbedo.a > 1e-4 ? gPoint / covered : vPoint;
    return gAlbedo.a;
}
)";

const char* const kSceneMain = R"(
uniform mat4 uViewProjection;
layout(location = 0) out vec4 fragColor;
void main() {
    vec3 base, n, p;
    float covered = sampleImpostor(vPoint, normalize(vPoint - vEye), base, n, p);
    vec4 world = vModel * vec4(p, 1.0);
    vec4 clip = uViewProjection * world;
    gl_FragDepth = clamp(0.5 * clip.z / clip.w + 0.5, 0.0, 1.0);
    vec3 specular = vec3(vLook.y);
    float metallic = vLook.w;
    // As the mesh program: a metal's highlight takes its colour.
    specular = mix(specular, base * (0.6 + specular), metallic);
    fragColor = aerial(shade(base * (1.0 - 0.6 * metallic), normalize(mat3(vModel) * n), world.xyz, specular, vLook.z),
                       world.xyz);
    // Last, so the derivatives above saw every pixel of the quad.
    if (covered < 0.5) discard;
}
)";

// The depth of the surface the sun's frames show (so the sculpture shades
// itself as the meshes do), pushed a few hundredths of its radius away
// from the sun: the lit side's points, read back from other frames, do not
// fall in its own shadow.
const char* const kShadowMain = R"(
uniform mat4 uViewProjection;
const float kPushAway = 0.04;
void main() {
    vec3 base, n, p;
    float covered = sampleImpostor(vPoint, -vToViewer, base, n, p);
    vec4 clip = uViewProjection * (vModel * vec4(p - vToViewer * (kPushAway * vSphere.w), 1.0));
    gl_FragDepth = clamp(0.5 * clip.z / clip.w + 0.5, 0.0, 1.0);
    if (covered < 0.5) discard;
}
)";

std::string sceneFragment() {
    return std::string("#version 330 core\n") + shaders::kLightingGlsl + kSampleGlsl + kSceneMain;
}
std::string shadowFragment() { return std::string("#version 330 core\n") + kSampleGlsl + kShadowMain; }

constexpr GLuint kCardFloats = 24;

}  // namespace

ImpostorCards::ImpostorCards()
    : scene_("impostor card", kCardVertex, sceneFragment().c_str()),
      shadow_("impostor shadow", kCardVertex, shadowFragment().c_str()) {
    for (const ShaderProgram* p : {&scene_, &shadow_}) {
        p->use();
        glUniform1i(p->uniform("uImpostorAlbedo"), kImpostorAlbedoUnit);
        glUniform1i(p->uniform("uImpostorNormalDepth"), kImpostorNormalDepthUnit);
        glUniform1f(p->uniform("uReach"), ImpostorAtlas::kReach);
    }
    glUseProgram(0);
    vao_ = gl::VertexArray::create();
    corners_ = gl::Buffer::create();
    instances_ = gl::Buffer::create();
    glBindVertexArray(vao_.get());
    const float corners[8] = {-1, -1, 1, -1, -1, 1, 1, 1};
    glBindBuffer(GL_ARRAY_BUFFER, corners_.get());
    glBufferData(GL_ARRAY_BUFFER, sizeof corners, corners, GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 2 * sizeof(float), nullptr);
    glBindBuffer(GL_ARRAY_BUFFER, instances_.get());
    for (GLuint a = 1; a <= 6; ++a) {
        glEnableVertexAttribArray(a);
        glVertexAttribPointer(a, 4, GL_FLOAT, GL_FALSE, kCardFloats * sizeof(float),
                              reinterpret_cast<const void*>((a - 1) * 4 * sizeof(float)));
        glVertexAttribDivisor(a, 1);
    }
    glBindVertexArray(0);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void ImpostorCards::send(const std::vector<ImpostorCard>& cards) {
    static_assert(sizeof(ImpostorCard) == kCardFloats * sizeof(float), "a card is 24 floats");
    count_ = cards.size();
    if (cards.empty()) return;
    glBindBuffer(GL_ARRAY_BUFFER, instances_.get());
    // Orphan and refill: the previous view's cards may still be in flight.
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(cards.size() * sizeof(ImpostorCard)), cards.data(),
                 GL_STREAM_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, 0);
}

void ImpostorCards::bindAtlas(const ImpostorAtlas& atlas, const ShaderProgram& program) const {
    glUniform1i(program.uniform("uViews"), atlas.settings().views);
    glUniform1f(program.uniform("uFramePixels"), static_cast<float>(atlas.settings().framePixels));
    glActiveTexture(GL_TEXTURE0 + kImpostorAlbedoUnit);
    glBindTexture(GL_TEXTURE_2D_ARRAY, atlas.albedo());
    glActiveTexture(GL_TEXTURE0 + kImpostorNormalDepthUnit);
    glBindTexture(GL_TEXTURE_2D_ARRAY, atlas.normalDepth());
    glActiveTexture(GL_TEXTURE0);
}

std::size_t ImpostorCards::draw() {
    glBindVertexArray(vao_.get());
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, static_cast<GLsizei>(count_));
    glBindVertexArray(0);
    return 1;
}

std::size_t ImpostorCards::drawScene(const ImpostorAtlas& atlas, const glm::mat4& viewProjection,
                                     const glm::vec3& eye) {
    if (count_ == 0) return 0;
    bindAtlas(atlas, scene_);
    glUniformMatrix4fv(scene_.uniform("uViewProjection"), 1, GL_FALSE, glm::value_ptr(viewProjection));
    glUniform3fv(scene_.uniform("uFrom"), 1, glm::value_ptr(eye));
    glUniform1i(scene_.uniform("uParallel"), 0);
    // A card always faces the eye: which way its corners wind does not matter.
    glDisable(GL_CULL_FACE);
    const std::size_t calls = draw();
    glEnable(GL_CULL_FACE);
    return calls;
}

std::size_t ImpostorCards::drawShadows(const ImpostorAtlas& atlas, const glm::mat4& lightViewProjection,
                                       const glm::vec3& toLight) {
    if (count_ == 0) return 0;
    shadow_.use();
    bindAtlas(atlas, shadow_);
    glUniformMatrix4fv(shadow_.uniform("uViewProjection"), 1, GL_FALSE, glm::value_ptr(lightViewProjection));
    const glm::vec3 l = glm::normalize(toLight);
    glUniform3fv(shadow_.uniform("uFrom"), 1, glm::value_ptr(l));
    glUniform1i(shadow_.uniform("uParallel"), 1);
    return draw();
}

}  // namespace hg::garden
