// The garden's OpenGL 3.3 core renderer: sculpture chunks in GPU buffers
// keyed by a stable chunk id, lit with a material per sculpture; the ground
// with its grid; lines (the morph triangle on the ground, tool gizmos) and
// the detail sphere.
//
// Colours. RenderMaterial, ground, line, sphere and clear colours are sRGB display
// values (what a colour picker shows); light colours and the ambient term
// are linear intensities. The scene is lit in linear HDR into the
// renderer's own multisampled target, shadowed by the sun, darkened by
// ambient occlusion, tone mapped and encoded to sRGB into the framebuffer
// that was bound at beginFrame (docs/rendering.md). Lines and the sphere
// are unlit and drawn over it as given.
//
// A view: beginFrame records the framebuffer bound then; draws are
// recorded; finishView renders them all (the shadow map needs every caster
// before the first lit pixel) into that framebuffer. endFrame finishes the
// open view, if any, and returns the frame's stats (one frame may hold
// several views: the headset's two eyes).
// Chunk uploads may happen between frames (the scheduler's upload stage
// runs before the render stage); their bytes count towards the stats that
// endFrame returns. The Renderer needs its GL context current whenever one
// of its functions runs, its destructor included.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <unordered_map>
#include <vector>

#include "garden/render/chunk_arena.h"
#include "garden/render/gl_objects.h"
#include "garden/render/impostor_atlas.h"
#include "garden/render/impostor_cards.h"
#include "garden/render/render_quality.h"
#include "garden/render/shader_program.h"
#include "garden/render/still_picture.h"
#include "polygonizer/mesh.h"

namespace hg::garden {

// The procedural detail a material shows (shaders.cpp's surfaceDetail),
// computed from the model-space position so it stays on the sculpture as
// it moves and scales, and a carve reveals the same material inside
// (docs/rendering.md "Materials"). An int in RenderMaterial, so that a
// material is plain numbers that can live in a per-draw buffer.
enum SurfaceKind : int {
    kSurfacePlain = 0,  // one colour
    kSurfaceStone,      // mottled, with dark and light grains
    kSurfaceMarble,     // pale, with dark winding veins
    kSurfaceBronze,     // metal, with a green patina in patches and on faces turned up
    kSurfaceClay,       // matte, faint smears of a darker and a lighter body
    kSurfacePlaster,    // matte white with a faint fine grain
    kSurfaceWood,       // growth rings around the model's vertical axis, with fine grain
    kSurfaceKindCount
};

// Everything a chunk's draw needs to shade it: plain floats and ints (see
// SurfaceKind), set on the mesh program in one place (renderer.cpp,
// drawRecord).
struct RenderMaterial {
    glm::vec3 baseColor{0.8f, 0.8f, 0.8f};  // sRGB
    float specular = 0.25f;                  // strength of the Blinn-Phong highlight, 0..1
    float shininess = 32.0f;                 // Blinn-Phong exponent: higher is smaller, sharper
    int kind = kSurfacePlain;                // SurfaceKind
    float metallic = 0.0f;                   // 0..1: the highlight takes the base colour, diffuse light fades
    float detailScale = 1.0f;                // model units per unit of the detail's pattern (about a tenth of
                                             // the sculpture: veins, rings, patches)
    int edges = 0;                           // 1: its triangles' edges drawn over it (the wireframe overlay)
    float cavity = 0.0f;                     // 0..1: grooves darkened and ridges lightened by the surface's
                                             // curvature on screen (the clay view's cavity shading)

    bool operator==(const RenderMaterial& o) const {
        return baseColor == o.baseColor && specular == o.specular && shininess == o.shininess && kind == o.kind &&
               metallic == o.metallic && detailScale == o.detailScale && edges == o.edges &&
               cavity == o.cavity;
    }
};

struct DirectionalLight {
    glm::vec3 direction{0.0f, 1.0f, 0.0f};  // from the scene towards the light; normalized on use
    glm::vec3 color{1.0f, 1.0f, 1.0f};      // linear intensity
};

constexpr int kMaxLights = 3;

// A light at a point: it falls with the square of the distance (intensity
// is its brightness 1 m away, as bright as a directional light of that
// colour) and smoothly to nothing at `range`.
struct PointLight {
    glm::vec3 position{0.0f, 3.0f, 0.0f};
    glm::vec3 color{1.0f, 1.0f, 1.0f};  // linear intensity at 1 m
    float range = 10.0f;                // metres
};

constexpr int kMaxPointLights = 8;

struct View {
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f};
    glm::vec3 eye{0.0f};                               // world position of the camera (specular)
    glm::ivec2 viewport{1, 1};                         // pixels of the bound framebuffer
    glm::vec4 clearColor{0.62f, 0.74f, 0.86f, 1.0f};  // sRGB sky at the horizon (deeper overhead)
    std::vector<DirectionalLight> lights;              // at most kMaxLights
    std::vector<PointLight> pointLights;               // at most kMaxPointLights
    glm::vec3 ambient{0.2f, 0.2f, 0.2f};               // linear
    // Aerial perspective: at this distance the horizon's colour covers 63%
    // of what lies there, 98% at twice it; 0 for none (docs/rendering.md,
    // "The ground and the haze").
    float hazeDistance = 0.0f;
    // Clouds in the sky: 0 a clear sky (a bare View's), 1 about half covered.
    float clouds = 0.0f;
};

struct GroundStyle {
    glm::vec3 color{0.42f, 0.47f, 0.38f};      // sRGB
    glm::vec3 lineColor{0.26f, 0.30f, 0.24f};  // sRGB
    float spacing = 1.0f;                      // metres between grid lines
    int majorEvery = 10;                       // a wider line every N lines (0: none)
    float lineWidth = 1.5f;                    // pixels
    float halfExtent = 100.0f;                 // the plane spans [-h, h] in x and z, at y = 0
    glm::vec2 gardenHalfExtent{0.0f};  // grid and stripes within |x| <= g.x, |z| <= g.y; a meadow beyond (0: the whole plane)
    float gridReach = 0.0f;         // the grid shows whole within this many metres of the eye, gone by twice (0: everywhere)
    float stripeWidth = 0.0f;       // metres a mown stripe (0: none)
};

enum class LineMode { Segments, Strip, Loop };

struct RenderStats {
    std::size_t trianglesDrawn = 0;
    std::size_t chunksDrawn = 0;      // chunk draws asked for (drawChunk calls that drew)
    std::size_t drawCalls = 0;        // GL draw calls for the scene, lines and sphere: one per batch of chunks
    std::size_t shadowDrawCalls = 0;  // GL draw calls of the casters into the shadow map
    std::size_t shadowMapsDrawn = 0;   // views whose shadow map was drawn
    std::size_t shadowMapsKept = 0;  // views that kept the map drawn before (nothing it shows changed)
    std::size_t bytesUploaded = 0;
    std::size_t impostorsDrawn = 0;   // cards drawn in place of far sculptures' chunks
    std::size_t impostorsBaked = 0;   // impostors rendered into the atlas since the last endFrame
    std::size_t sculpturesHidden = 0;  // left out as hidden behind nearer ones (wasHidden said so)
    std::size_t visibilityTests = 0;   // boxes drawn in occlusion queries (visibility_queries.h)
    std::size_t skyBakes = 0;          // the sky's cube map baked again (its look changed: sky_pass.h)
    std::size_t picturesKept = 0;       // views that showed the picture held (nothing in it changed)
    std::size_t picturesSharpened = 0;  // views drawn again at a still quality (setStillQualities)
    // GPU milliseconds per pass of the latest view the GPU has finished
    // (GL timer queries, read without waiting: a view or a few behind); -1
    // where a pass did not run or no result is in yet.
    float gpuShadowMs = -1.0f;
    float gpuSceneMs = -1.0f;
    float gpuOcclusionMs = -1.0f;
    float gpuPostMs = -1.0f;
    float gpuMs() const;  // the measured passes together; -1 when none is
};

class ChunkBatch;
class SceneTargets;
class PostProcess;
class GpuTimers;
class ShadowPass;
class OcclusionPass;
class SkyPass;
class VisibilityQueries;
class HeldOutput;

class Renderer {
public:
    // Compiles the programs; throws GlError naming a shader that fails.
    Renderer();
    ~Renderer();
    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // --- chunk buffers -------------------------------------------------------
    // Uploads `mesh` for `id` unless that id already holds `version`; returns
    // the bytes sent to the GPU (0 when it was current). An empty mesh is
    // recorded (has() is true) and draws nothing. Throws std::invalid_argument
    // for a malformed mesh (sizes not multiples of 3, normals of another
    // length than positions, an index past the last vertex).
    std::size_t upload(ChunkId id, std::uint64_t version, const poly::Mesh& mesh);
    bool has(ChunkId id, std::uint64_t version) const;
    bool has(ChunkId id) const;
    // The model-space box around chunk `id`'s vertices; false when it has
    // no buffers or no triangles.
    bool bounds(ChunkId id, glm::vec3& lo, glm::vec3& hi) const;
    void drop(ChunkId id);
    std::size_t chunkCount() const { return chunks_.size(); }
    std::size_t residentBytes() const { return residentBytes_; }
    const ChunkArena& arena() const { return *arena_; }
    // Background defragmentation of the chunk buffers: at most about
    // `byteBudget` bytes moved on the GPU (ChunkArena::compact). Call
    // between frames; the bytes moved.
    std::size_t compactArena(std::size_t byteBudget) { return arena_->compact(byteBudget); }

    // --- batching ------------------------------------------------------------
    // Chunks go out as one multi-draw per pass where the context can
    // (multiDrawAvailable(): GL 4.3), else one draw call each; both give
    // the same pixels. Asking for multi-draw where it is missing leaves it
    // off; returns whether it is on.
    bool setMultiDraw(bool on);
    bool multiDraw() const { return multiDraw_; }

    // --- impostors (impostor_atlas.h, impostor_cards.h) -------------------------
    // Made on first use: a renderer that never draws one compiles nothing for them.
    bool hasImpostor(ImpostorKey key, std::uint64_t version) const;
    // Renders impostor `key` at `version` from the resident chunks `ids`
    // (one sculpture's, in model space) with `material`. False when one of
    // them has no buffers, they hold no triangles, or every layer of the
    // atlas holds an impostor drawn in this frame. Call between views (it
    // draws into the atlas; the bound framebuffer and viewport are kept).
    bool bakeImpostor(ImpostorKey key, std::uint64_t version, const std::vector<ChunkId>& ids,
                      const RenderMaterial& material);
    // A card for impostor `key` (current at `version`) placed by `model`,
    // lit with `material`'s highlight. False when none is current.
    bool drawImpostor(ImpostorKey key, std::uint64_t version, const glm::mat4& model, const RenderMaterial& material);
    // Null before the first impostor.
    const ImpostorAtlas* impostorAtlas() const { return atlas_.get(); }
    // Frames per side and pixels per frame of the atlas made on first use
    // (a test's smaller atlas); no effect once it is made.
    void setImpostorSettings(const ImpostorSettings& settings) { impostorSettings_ = settings; }

    // --- the shadow map -------------------------------------------------------------
    // On by default: a view whose shadow map would be drawn from the same
    // casters (the same chunks, placements and arena contents, the same
    // cards and atlas) over the same box from the same sun at the same
    // size keeps the map drawn before instead: the headset's second eye,
    // and every frame of a still garden. Off: drawn every view (benches
    // that measure the pass).
    void setShadowReuse(bool on) { shadowReuse_ = on; }
    bool shadowReuse() const { return shadowReuse_; }

    // --- the sky (sky_pass.h) -------------------------------------------------------
    // On by default: the sky's gradient and clouds baked into a cube map
    // while its look holds. Off: evaluated at every sky pixel (the peer of
    // tests and benches); the pixels differ only by the map's filtering.
    void setSkyBaked(bool on);
    bool skyBaked() const;

    // --- hidden sculptures (visibility_queries.h) --------------------------------
    // On by default. Off forgets every result; wasHidden is then always false.
    void setOcclusionCulling(bool on);
    bool occlusionCulling() const { return occlusionCulling_; }
    // Whether the caller's object `key` (a sculpture, its world box now
    // lo..hi) was hidden behind nearer things when its box was last tested
    // in this view's place in the frame, and that result is still trusted;
    // counted in the stats as hidden, since the caller then leaves it out
    // (drawChunk, seen false).
    bool wasHidden(std::uint64_t key, const glm::vec3& worldLo, const glm::vec3& worldHi);
    // Tests `key`'s world box after this view's scene pass, for a later frame's wasHidden.
    void testVisibility(std::uint64_t key, const glm::vec3& worldLo, const glm::vec3& worldHi);
    // What the world box lo..hi covers changed (a sculpture moved, edited,
    // remeshed or taken away, before or after): results it may have hidden
    // are forgotten, so what it hid is drawn from the next view on.
    void forgetHiddenBehind(const glm::vec3& worldLo, const glm::vec3& worldHi);

    // --- quality -------------------------------------------------------------
    // What views are drawn at (and what the caller's level of detail follows).
    void setQuality(const RenderQuality& quality) { quality_ = quality; }
    const RenderQuality& quality() const { return quality_; }

    // --- a still view (still_picture.h) -----------------------------------------
    // Off by default. On: a view whose inputs equal those of the picture
    // drawn last (the same camera, lights and sky into the same framebuffer,
    // the same draws of the same meshes and cards) is not drawn again: the
    // held picture is copied into the output (held_output.h) and what
    // follows is drawn over it (RenderStats::picturesKept). Such a view reports no GPU time, so
    // it does not steer the automatic quality. The desktop's window.
    void setPictureReuse(bool on);
    bool pictureReuse() const { return pictureReuse_; }
    // With reuse on: a view held a few views in a row is drawn once more at
    // each of `stills` in turn, then held (StillPicture's counts;
    // RenderStats::picturesSharpened); their GPU time is not reported
    // either. The automatic mode's quality while the visitor moves,
    // sharpened when they stop. Empty: never.
    void setStillQualities(std::vector<RenderQuality> stills) { stillQualities_ = std::move(stills); }
    const std::vector<RenderQuality>& stillQualities() const { return stillQualities_; }

    // --- a frame -------------------------------------------------------------
    // Starts a view into the framebuffer bound now, of view.viewport pixels
    // (finishing an open one first). Throws std::invalid_argument for more
    // than kMaxLights directional or kMaxPointLights point lights.
    void beginFrame(const View& view);
    // Draws an uploaded chunk with `model` (rotation, translation, uniform or
    // not scale: normals use the inverse transpose). False when `id` has no
    // buffers, so the caller can see it is not resident yet. `seen` false:
    // only its shadow (a hidden sculpture's chunk still casts).
    bool drawChunk(ChunkId id, const glm::mat4& model, const RenderMaterial& material, bool seen = true);
    void drawGround(const GroundStyle& ground);
    // Unlit lines of one pixel; `depthTested` false draws them over
    // everything (gizmos that must stay visible).
    void drawLines(const std::vector<glm::vec3>& points, const glm::vec4& color, LineMode mode = LineMode::Strip,
                   bool depthTested = true);
    // The detail sphere: wireframe (three great circles and the outline seen
    // from the eye) or a solid shell, blended when color.a < 1 (draw it
    // after the opaque geometry).
    void drawSphere(const glm::vec3& center, float radius, const glm::vec4& color, bool wireframe);

    // Renders the recorded view into its framebuffer (colour and depth);
    // afterwards other drawing (panels) may follow there. Nothing when no
    // view is open.
    void finishView();

    const RenderStats& stats() const { return stats_; }
    // Finishes the open view; the frame's stats (uploads since the last
    // endFrame included); resets them.
    RenderStats endFrame();

private:
    // A chunk's mesh lives in the arena; this is what the renderer keeps beside it.
    struct ChunkRecord {
        std::uint64_t version = 0;
        std::size_t indexCount = 0;
        bool hasNormals = false;
        std::size_t bytes = 0;
        glm::vec3 lo{0.0f}, hi{0.0f};  // model-space bounds, for fitting the shadow map
    };
    struct LitUniforms {
        GLint eye, ambient, lightCount, lightDir, lightColor, pointCount, pointPosition, pointColor, pointRange, haze,
            hazeDistance;
    };
    struct ShadowUniforms {
        GLint enabled, matrix, offset, texel;
    };

    // A lit draw waiting for finishView: a chunk, or the ground.
    struct SceneDraw {
        bool ground = false;
        bool castOnly = false;  // hidden: into the shadow map only
        ChunkId id = 0;
        glm::mat4 model{1.0f};
        RenderMaterial material;
        GroundStyle groundStyle;
    };
    // An unlit draw after the composite: lines (points from `first` in the
    // view's line points) or the solid sphere.
    struct FlatDraw {
        GLenum primitive = GL_LINES;
        bool sphere = false;
        GLsizei first = 0, count = 0;
        glm::mat4 model{1.0f};
        glm::vec4 color{1.0f};
        bool depthTested = true;
    };

    static LitUniforms litUniforms(const ShaderProgram& p);
    static ShadowUniforms shadowUniforms(const ShaderProgram& p);
    void ensureImpostors();
    // Frame lighting and the shadow for the bound program whose locations are `u`.
    void setLighting(const LitUniforms& u, const ShadowUniforms& s, bool shadowed) const;
    // The view's chunk draws into batches_, the casters among them (within
    // the shadow distance) into shadowBatch_ with the world box they span.
    void gatherChunks(const RenderQuality& q, glm::vec3& lo, glm::vec3& hi);
    bool renderShadows(const RenderQuality& q, const glm::vec3& lo, const glm::vec3& hi);
    void renderScene(const RenderQuality& q, bool shadowed);
    // The shadow, scene and occlusion passes at `q` into the scene targets.
    OcclusionImage drawPicture(const RenderQuality& q);
    // A kept view: its hidden sculptures' boxes against the held depth.
    void testVisibilityOverTheHeldPicture();
    // The picture into the output framebuffer: composited, or for a kept
    // view copied from the held output (composited there first if need be).
    void writeOutput(bool kept, const OcclusionImage& occlusion, const RenderQuality& shown);
    // Lines, the solid sphere and the wireframe over the output.
    void drawOverTheOutput();
    // Whether the open view's inputs equal those of the picture held.
    bool holdsThisView() const;
    // The open view's inputs as the held picture's (its draws are taken).
    void holdThisView();
    // The wireframe overlay: the edges of the chunks whose material asks.
    void drawEdges();
    void drawGroundNow(const GroundStyle& ground);
    void drawFlatNow(const FlatDraw& d);

    // The mesh program compiled for one surface kind (HG_KIND): a software
    // rasterizer runs every branch of a shader, so one program for all six
    // materials made each pixel pay for all six (docs/rendering.md,
    // "Programs made to measure"). Made when a kind is first drawn.
    struct MeshProgram {
        ShaderProgram program;
        LitUniforms lit{};
        ShadowUniforms shadow{};
        GLint viewProjection = -1, bump = -1;
    };
    MeshProgram& meshProgram(int kind);
    // The same, compiled to bake impostors (HG_BAKE).
    ShaderProgram& bakeProgram(int kind);

    std::array<std::unique_ptr<MeshProgram>, kSurfaceKindCount> meshPrograms_;

    ShaderProgram groundProgram_;
    ShaderProgram flatProgram_;
    LitUniforms groundLit_{};
    ShadowUniforms groundShadow_{};
    struct {
        GLint viewProjection, groundColor, lineColor, spacing, lineWidth, majorEvery, gardenHalfExtent, gridReach,
            stripeWidth;
    } ground_{};
    struct {
        GLint model, view, projection, color;
    } flat_{};

    std::unordered_map<ChunkId, ChunkRecord> chunks_;
    std::size_t residentBytes_ = 0;

    gl::VertexArray groundVao_;
    gl::Buffer groundVbo_;
    gl::VertexArray streamVao_;  // lines: points re-sent each call
    gl::Buffer streamVbo_;
    gl::VertexArray sphereVao_;  // unit sphere for the solid detail sphere
    gl::Buffer sphereVbo_;
    gl::Buffer sphereEbo_;
    GLsizei sphereIndexCount_ = 0;

    RenderQuality quality_;
    std::unique_ptr<SceneTargets> targets_;
    std::unique_ptr<ShadowPass> shadow_;
    std::unique_ptr<OcclusionPass> occlusion_;
    std::unique_ptr<SkyPass> sky_;
    std::unique_ptr<VisibilityQueries> visibility_;  // made on first use
    bool occlusionCulling_ = true;
    int viewsThisFrame_ = 0;
    std::uint64_t frames_ = 0;  // endFrame calls
    std::unique_ptr<PostProcess> post_;
    std::unique_ptr<GpuTimers> timers_;
    std::unique_ptr<ChunkArena> arena_;  // every chunk's mesh
    // The open view's chunk draws, a batch per surface kind (each drawn
    // with its kind's program).
    std::array<std::unique_ptr<ChunkBatch>, kSurfaceKindCount> batches_;
    std::unique_ptr<ChunkBatch> shadowBatch_;  // those of them that cast the sun's shadow
    // Impostors: the atlas, the cards, the mesh program built to bake, the
    // batch a bake draws, and the view's cards.
    ImpostorSettings impostorSettings_;
    std::unique_ptr<ImpostorAtlas> atlas_;
    std::unique_ptr<ImpostorCards> cards_;
    std::array<std::unique_ptr<ShaderProgram>, kSurfaceKindCount> bakePrograms_;
    std::unique_ptr<ChunkBatch> bakeBatch_;
    LitUniforms cardLit_{};
    ShadowUniforms cardShadow_{};
    std::vector<ImpostorCard> cardDraws_;
    bool cardsCast_ = false;  // a card is within the shadow's reach in the open view
    // What the shadow map holds now (setShadowReuse): the casters' box, the
    // sun, the map's size, the arena's and the atlas's generations, and
    // the chunks and cards drawn into it.
    struct ShadowInputs {
        glm::vec3 lo{0.0f}, hi{0.0f}, toLight{0.0f};
        int size = 0;
        std::size_t arena = 0, bakes = 0;
        bool operator==(const ShadowInputs& o) const {
            return lo == o.lo && hi == o.hi && toLight == o.toLight && size == o.size && arena == o.arena &&
                   bakes == o.bakes;
        }
    };
    bool shadowReuse_ = true;
    std::optional<ShadowInputs> shadowHolds_;
    std::unique_ptr<ChunkBatch> shadowHeldCasters_;
    std::vector<ImpostorCard> shadowHeldCards_;
    bool multiDraw_ = false;

    // The picture the scene targets hold (setPictureReuse) and what it was drawn from.
    bool pictureReuse_ = false;
    std::vector<RenderQuality> stillQualities_;
    std::unique_ptr<StillPicture> still_;
    std::unique_ptr<HeldOutput> heldOutput_;  // made at the first view kept
    struct {
        View view;
        GLuint output = 0;
        std::vector<SceneDraw> draws;
        std::vector<ImpostorCard> cards;
        std::size_t arena = 0, bakes = 0;
        bool skyBaked = false;
    } held_;
    int viewsMeasured_ = 0, viewsNotMeasured_ = 0;  // this frame's: drawn at quality_, or kept or sharpened

    View view_;
    bool viewOpen_ = false;
    GLuint output_ = 0;  // the framebuffer bound at beginFrame
    std::vector<SceneDraw> sceneDraws_;
    std::vector<FlatDraw> flatDraws_;
    std::vector<glm::vec3> linePoints_;
    RenderStats stats_;
};

}  // namespace hg::garden
