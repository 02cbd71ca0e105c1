// The last pass of a view: every sample of the linear HDR scene is exposed,
// darkened by ambient occlusion where the scene pass said how much of it is
// ambient light, tone mapped (Khronos PBR Neutral) and only then averaged,
// so anti-aliased edges between a bright sky and a dark sculpture keep
// their coverage; the average is encoded to sRGB. The scene's depth goes
// along (sample 0), so lines and panels drawn afterwards are depth tested
// against the sculptures. docs/rendering.md explains the order. One program
// per configuration (samples, occlusion, and whether it resolves for a
// stretch), compiled when first met (docs/rendering.md, "Programs made to
// measure"); a scene drawn smaller than the output is resolved at its own
// size and encoded first, then stretched bilinearly in display space by a
// second, small program.
#pragma once

#include <glm/vec2.hpp>

#include <array>
#include <map>
#include <optional>
#include <tuple>

#include "garden/render/gl_objects.h"
#include "garden/render/occlusion_pass.h"
#include "garden/render/render_targets.h"
#include "garden/render/shader_program.h"

namespace hg::garden {

class PostProcess {
public:
    PostProcess();  // throws GlError naming a shader that fails

    // Draws into the bound framebuffer, whose viewport the caller has set
    // to the scene's size. `occlusion`: the occlusion pass's image (its
    // texture 0: none). At half resolution each scene pixel takes the four
    // occlusion texels around it weighted by distance and by how near their
    // depth is to its own (a joint bilateral upsample), so a hollow's
    // darkness does not bleed over a silhouette onto what lies behind it.
    // `output`: the pixels of the bound framebuffer's view, which the scene
    // (drawn at the render scale) is stretched over, bilinearly between
    // resolved, encoded scene pixels (lines and panels, drawn afterwards at the
    // output's size, stay sharp); `smooth` false: the nearest scene pixel.
    void composite(const SceneTargets& scene, const OcclusionImage& occlusion, float exposure, glm::ivec2 output,
                   bool smooth);
    ~PostProcess();

private:
    // What a composite's program is compiled for (withDefines).
    struct Configuration {
        int samples = 1;
        int occlusion = 0;  // 0 none, 1 at the scene's size, 2 coarser (the joint bilateral upsample)
        bool resolve = false;  // into the resolved texture, for the stretch (else: straight to the output)
        bool operator<(const Configuration& o) const {
            return std::tie(samples, occlusion, resolve) < std::tie(o.samples, o.occlusion, o.resolve);
        }
    };
    struct Variant {
        ShaderProgram program;
        GLint exposure = -1, toScene = -1, occlusionScale = -1;
    };
    const Variant& variant(const Configuration& c);
    // The resolved scene, bilinearly over the output, with the depth of a
    // scene of `samples` (compiled when first met, per sampler type).
    struct Stretch {
        ShaderProgram program;
        GLint size = -1, toScene = -1;
    };
    const Stretch& stretch(int samples);
    void ensureResolved(glm::ivec2 size);

    std::map<Configuration, Variant> variants_;
    std::array<std::optional<Stretch>, 2> stretches_;  // one sample, several
    gl::Texture resolved_;   // RGBA8 at the scene's size: tone mapped, averaged, sRGB-encoded
    gl::Framebuffer resolvedTarget_;
    glm::ivec2 resolvedSize_{0};
    gl::VertexArray empty_;  // the fullscreen triangle comes from gl_VertexID
};

}  // namespace hg::garden
