// Drawing impostors (impostor_atlas.h; docs/rendering.md, "Impostors"):
// every card of a view in one instanced draw. A card is a square facing the
// eye around the sculpture's bounding sphere; each pixel casts its ray
// through the four frames of the atlas nearest the direction it is seen
// from, each where the ray meets that frame's plane (so neighbouring
// frames agree at the centre instead of ghosting), and blends their
// colour, normal and depth. The card then writes the depth of the surface
// it shows (it meets the ground and its neighbours as the mesh would, and
// ambient occlusion reads it) and is lit by the same shade() as the meshes.
// Into the sun's shadow map the same card is drawn facing the sun, from
// the frames nearest the sun's direction: a far sculpture keeps its shadow.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstddef>
#include <vector>

#include "garden/render/gl_objects.h"
#include "garden/render/shader_program.h"

namespace hg::garden {

class ImpostorAtlas;

// One card: the sculpture's placement, the impostor's sphere (model-space
// centre and radius) and layer, and the material's highlight.
struct ImpostorCard {
    glm::mat4 model{1.0f};
    glm::vec4 sphere{0.0f};  // xyz centre, w radius (model units)
    glm::vec4 look{0.0f};    // layer, specular strength, shininess, metallic
};

class ImpostorCards {
public:
    ImpostorCards();  // throws GlError naming a broken shader

    // The lit program: the caller sets its lighting (shaders.h's
    // kLightingGlsl uniforms) before drawScene.
    const ShaderProgram& sceneProgram() const { return scene_; }

    // The view's cards to the GPU (before either draw below).
    void send(const std::vector<ImpostorCard>& cards);
    // Into the bound framebuffer (depth test on): with the scene program in
    // use. Returns the draw calls made (0 or 1).
    std::size_t drawScene(const ImpostorAtlas& atlas, const glm::mat4& viewProjection, const glm::vec3& eye);
    // Into the bound shadow map (depth only), facing `toLight`.
    std::size_t drawShadows(const ImpostorAtlas& atlas, const glm::mat4& lightViewProjection, const glm::vec3& toLight);

private:
    void bindAtlas(const ImpostorAtlas& atlas, const ShaderProgram& program) const;
    std::size_t draw();

    ShaderProgram scene_;
    ShaderProgram shadow_;
    gl::VertexArray vao_;
    gl::Buffer corners_;
    gl::Buffer instances_;
    std::size_t count_ = 0;
};

}  // namespace hg::garden
