// Impostors: a sculpture far away drawn as a card that shows it from a
// few dozen pre-rendered directions (issue 25; docs/rendering.md,
// "Impostors"). The atlas keeps them: per impostor one layer of two 2D
// array textures, each layer a grid of views x views frames (directions on
// the upper hemisphere, hemi-octahedral: the square's edges are the horizon,
// its centre straight down from above). A frame holds, premultiplied by
// coverage, the surface's colour before lighting (sRGB) and its model-space
// normal with its depth along the frame's direction (16-bit float), so the
// card is lit like the meshes, by the garden's lights and the sun's shadow,
// whatever way the sculpture turns; with three mip levels made from
// premultiplied averages (no dark fringes, no depth pulled to the card).
//
// Impostors are keyed by what they show (ImpostorKey, chosen by the
// caller: copies of one source with one material share one) and a version
// (a new version is a new bake into the same layer). Layers are reused
// least recently drawn first; the atlas grows, up to its most layers, by
// making new textures and copying the old ones' layers into them on the
// GPU (GL 4.3; without it, what was baked is baked again as it is wanted).
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "garden/render/chunk_batch.h"
#include "garden/render/gl_objects.h"
#include "garden/render/shader_program.h"

namespace hg::garden {

using ImpostorKey = std::uint64_t;

struct ImpostorSettings {
    int views = 8;         // frames along each side of the hemi-octahedral grid (views^2 directions)
    int framePixels = 64;  // pixels on a frame's side
    int maxLayers = 64;    // impostors held at most (each views * framePixels squared, about 4 MiB at 8 x 64)
};

// What a card needs of a baked impostor.
struct ImpostorEntry {
    int layer = -1;
    glm::vec3 centre{0.0f};  // model-space centre of the views
    float radius = 0.0f;     // model-space radius of the sphere holding the sculpture
};

class ImpostorAtlas {
public:
    explicit ImpostorAtlas(const ImpostorSettings& settings = {});  // throws GlError naming a broken shader
    ~ImpostorAtlas();
    ImpostorAtlas(const ImpostorAtlas&) = delete;
    ImpostorAtlas& operator=(const ImpostorAtlas&) = delete;

    const ImpostorSettings& settings() const { return settings_; }
    // Frame half-width in sphere radii: a margin so the lower mip levels
    // do not bleed one frame into the next.
    static constexpr float kReach = 1.08f;

    bool has(ImpostorKey key, std::uint64_t version) const;
    // The impostor, marked drawn in this frame (it is not given up for
    // another before the next nextFrame()); null when none is current.
    const ImpostorEntry* use(ImpostorKey key, std::uint64_t version);
    void nextFrame() { ++frame_; }

    // Renders every frame of impostor `key` from `batch` (the sculpture's
    // chunks, with model-space records) with `program` (the mesh program
    // built with HG_BAKE; in use, its uniforms other than those set here
    // set by the caller), around the sphere (centre, radius) in model
    // units. False when every layer holds an impostor drawn this frame.
    // Leaves framebuffer 0 bound and the viewport and sRGB writes as it
    // found them.
    bool bake(ImpostorKey key, std::uint64_t version, ChunkBatch& batch, ChunkArena& arena, bool multiDraw,
              const ShaderProgram& program, const glm::vec3& centre, float radius);

    GLuint albedo() const { return albedo_.get(); }
    GLuint normalDepth() const { return normalDepth_.get(); }
    std::size_t count() const { return entries_.size(); }
    std::size_t layers() const { return static_cast<std::size_t>(layers_); }
    std::size_t bytes() const;  // GPU memory of the textures
    std::size_t bakes() const { return bakes_; }  // since construction

    // The view from direction `toViewer` (model space, from the centre) of
    // frame (i, j): the camera the bake uses, in model units; public so a
    // test can check the card's sampling against it.
    static glm::vec3 frameDirection(int i, int j, int views);
    static glm::mat4 frameViewProjection(const glm::vec3& toViewer, const glm::vec3& centre, float radius);

private:
    struct Slot {
        ImpostorEntry entry;
        std::uint64_t version = 0;
        std::uint64_t lastUsed = 0;
    };
    // A layer for `key`: its own, a free one, a new one (growing), or the
    // least recently drawn; -1 when every layer was drawn this frame.
    int layerFor(ImpostorKey key);
    void grow(int layers);
    void downsample(int layer);

    ImpostorSettings settings_;
    ShaderProgram downsample_;
    GLint downsampleLevel_ = -1;
    GLint downsampleLayer_ = -1;
    gl::Texture albedo_;
    gl::Texture normalDepth_;
    gl::Renderbuffer depth_;
    gl::Framebuffer fbo_;
    gl::VertexArray emptyVao_;
    int layers_ = 0;
    std::unordered_map<ImpostorKey, Slot> entries_;
    std::vector<ImpostorKey> owner_;  // per layer
    std::vector<bool> owned_;
    std::uint64_t frame_ = 1;
    std::size_t bakes_ = 0;
};

// The mip levels below the frames' own.
constexpr int kImpostorMipLevels = 3;
// Texture units the atlas's two textures are read from (its mips and the
// cards; the shadow map is on 3, draw records on 4).
constexpr GLint kImpostorAlbedoUnit = 5;
constexpr GLint kImpostorNormalDepthUnit = 6;

}  // namespace hg::garden
