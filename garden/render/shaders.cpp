#include "garden/render/shaders.h"

#include <string>

namespace hg::garden::shaders {

// Shared by the lit programs: the frame's lights, the sun's shadow and the
// split of the light into what ambient occlusion may dim (alpha) and not.
#define HG_LIGHTING_GLSL                                                              \
    HG_SRGB_GLSL                                                                      \
    "uniform vec3 uEye;\n"                                                            \
    "uniform vec3 uAmbient;\n"                                                        \
    "uniform int uLightCount;\n"                                                      \
    "uniform vec3 uLightDir[3];\n"                                                    \
    "uniform vec3 uLightColor[3];\n"                                                  \
    "uniform int uPointCount;\n"                                                      \
    "uniform vec3 uPointPosition[8];\n"                                               \
    "uniform vec3 uPointColor[8];\n"                                                  \
    "uniform float uPointRange[8];\n"                                                 \
    "const float kDirectOcclusion = 0.35;\n"                                          \
    "uniform bool uShadows;\n"                                                        \
    "uniform sampler2DShadow uShadowMap;\n"                                           \
    "uniform mat4 uShadowMatrix;\n"                                                   \
    "uniform float uShadowOffset;\n"                                                  \
    "uniform float uShadowTexel;\n"                                                   \
    "float sunShadow(vec3 p, vec3 n, vec3 l) {\n"                                     \
    "    if (!uShadows) return 1.0;\n"                                                \
    "    float slope = 1.0 - clamp(dot(n, l), 0.0, 1.0);\n"                           \
    "    vec4 s = uShadowMatrix * vec4(p + n * uShadowOffset * (0.5 + slope), 1.0);\n" \
    "    vec3 c = s.xyz / s.w;\n"                                                     \
    "    /* receiver plane: how depth changes across the map, so taps a few */\n"     \
    "    /* texels away compare against the surface's own plane (no acne) */\n"      \
    "    vec3 dx = dFdx(c), dy = dFdy(c);\n"                                          \
    "    float det = dx.x * dy.y - dx.y * dy.x;\n"                                    \
    "    vec2 plane = abs(det) > 1e-12\n"                                             \
    "        ? vec2(dy.y * dx.z - dx.y * dy.z, dx.x * dy.z - dy.x * dx.z) / det : vec2(0.0);\n" \
    "    if (c.x <= 0.0 || c.y <= 0.0 || c.x >= 1.0 || c.y >= 1.0) return 1.0;\n"     \
    "    float lit = 0.0;\n"                                                          \
    "    for (int y = -1; y <= 1; ++y)\n"                                             \
    "        for (int x = -1; x <= 1; ++x) {\n"                                       \
    "            vec2 o = vec2(x, y) * uShadowTexel;\n"                               \
    "            float ref = c.z + clamp(dot(o, plane), -0.01, 0.01);\n"              \
    "            lit += texture(uShadowMap, vec3(c.xy + o, min(ref, 1.0)));\n"        \
    "        }\n"                                                                     \
    "    return lit / 9.0;\n"                                                         \
    "}\n"                                                                             \
    "vec3 blinnPhong(vec3 base, vec3 n, vec3 l, vec3 v, vec3 specular, float shininess) {\n" \
    "    float ndl = dot(n, l);\n"                                                    \
    "    if (ndl <= 0.0) return vec3(0.0);\n"                                         \
    "    float ndh = max(dot(n, normalize(l + v)), 0.0);\n"                           \
    "    return base * ndl + specular * pow(ndh, shininess);\n"                       \
    "}\n"                                                                             \
    "/* specular: the highlight's colour (a metal's takes its own colour) */\n"      \
    "vec4 shade(vec3 base, vec3 n, vec3 p, vec3 specular, float shininess) {\n"      \
    "    vec3 v = normalize(uEye - p);\n"                                             \
    "    vec3 ambient = uAmbient * base;\n"                                           \
    "    vec3 direct = vec3(0.0);\n"                                                  \
    "    for (int i = 0; i < uLightCount; ++i) {\n"                                   \
    "        float lit = i == 0 ? sunShadow(p, n, uLightDir[0]) : 1.0;\n"             \
    "        direct += lit * uLightColor[i] * blinnPhong(base, n, uLightDir[i], v, specular, shininess);\n" \
    "    }\n"                                                                         \
    "    for (int i = 0; i < uPointCount; ++i) {\n"                                   \
    "        vec3 d = uPointPosition[i] - p;\n"                                       \
    "        float r = length(d);\n"                                                  \
    "        if (r >= uPointRange[i]) continue;\n"                                    \
    "        float x = r / uPointRange[i];\n"                                         \
    "        float window = clamp(1.0 - x * x * x * x, 0.0, 1.0);\n"                  \
    "        float falloff = window * window / max(r * r, 0.01);\n"                   \
    "        vec3 l = d / max(r, 1e-4);\n"                                            \
    "        direct += falloff * uPointColor[i] * blinnPhong(base, n, l, v, specular, shininess);\n" \
    "    }\n"                                                                         \
    "    vec3 w = vec3(0.2126, 0.7152, 0.0722);\n"                                    \
    "    float a = dot(ambient, w), d = dot(direct, w);\n"                            \
    "    /* occlusion dims the ambient light, and a third of the direct: form reads */\n" \
    "    return vec4(ambient + direct, (a + kDirectOcclusion * d) / max(a + d, 1e-5));\n" \
    "}\n"                                                                             \
    "/* Aerial perspective: the sky's horizon colour over what lies far off, */\n"   \
    "/* so the lawn meets the sky without an edge and depth reads in a big */\n"    \
    "/* garden (docs/rendering.md, \"The ground and the haze\"). The haze is */\n" \
    "/* not occluded: alpha keeps the share of the hazed colour occlusion */\n"   \
    "/* may dim. */\n"                                                             \
    "uniform vec3 uHaze;\n"                                                          \
    "uniform float uHazeDistance;\n"                                                 \
    "vec4 aerial(vec4 lit, vec3 p) {\n"                                              \
    "    if (uHazeDistance <= 0.0) return lit;\n"                                    \
    "    float r = length(p - uEye) / uHazeDistance;\n"                               \
    "    float f = 1.0 - exp(-r * r);\n"                                             \
    "    vec3 c = mix(lit.rgb, uHaze, f);\n"                                         \
    "    vec3 w = vec3(0.2126, 0.7152, 0.0722);\n"                                   \
    "    float dimmable = lit.a * (1.0 - f) * dot(lit.rgb, w);\n"                   \
    "    return vec4(c, clamp(dimmable / max(dot(c, w), 1e-5), 0.0, 1.0));\n"       \
    "}\n"

// The materials' procedural detail (docs/rendering.md, "Materials").
const char* const kSurfaceDetailGlsl = R"(
// Value noise in model space (hash after Dave Hoskins' hash13), and its sum
// over four octaves, about 0..1 with mean 0.5. An octave finer than a pixel
// (`pixel`: p's change across one) fades to its mean and is not evaluated:
// far surfaces cost fewer octaves and do not shimmer (docs/rendering.md,
// "Materials").
float hash3(vec3 p) {
    p = fract(p * vec3(0.1031, 0.1030, 0.0973));
    p += dot(p, p.yxz + 33.33);
    return fract((p.x + p.y) * p.z);
}
float noise3(vec3 p) {
    vec3 i = floor(p), f = fract(p);
    vec3 u = f * f * (3.0 - 2.0 * f);
    vec2 e = vec2(1.0, 0.0);
    return mix(mix(mix(hash3(i), hash3(i + e.xyy), u.x), mix(hash3(i + e.yxy), hash3(i + e.xxy), u.x), u.y),
               mix(mix(hash3(i + e.yyx), hash3(i + e.xyx), u.x), mix(hash3(i + e.yxx), hash3(i + 1.0), u.x), u.y), u.z);
}
// 1 while a pattern of `frequency` (per pattern unit) is larger than a
// pixel, fading to 0 as it shrinks below one: no shimmer far away.
float resolved(float frequency, float pixel) { return 1.0 - smoothstep(0.3, 0.8, frequency * pixel); }
float fbm(vec3 p, float pixel) {
    float sum = 0.0, amplitude = 0.5;
    for (int o = 0; o < 4; ++o) {
        float seen = resolved(1.0, pixel);
        sum += amplitude * (seen > 0.0 ? mix(0.5, noise3(p), seen) : 0.5);
        p = p * 2.03 + vec3(1.7, 9.2, 3.1);
        pixel *= 2.03;
        amplitude *= 0.5;
    }
    return sum / 0.9375;
}
// The material's colour, highlight and metalness at model point q (in
// pattern units) with world normal n; `pixel` is q's change across a pixel.
// `height` (pattern units, out of the surface) is the same detail as
// relief: grains stand out of stone, veins sink into marble, rings into
// wood; it fades with the colour where a pattern shrinks below a pixel.
void surfaceDetail(int kind, vec3 q, vec3 n, float pixel, inout vec3 base, inout vec3 specular,
                   inout float shininess, inout float metallic, out float height) {
    height = 0.0;
    if (kind == 1) {  // stone: mottled, dark and light grains
        float mottle = fbm(q * 0.5, 0.5 * pixel);
        base *= 0.82 + 0.36 * mottle;
        float grain = noise3(q * 9.0);
        float seen = resolved(9.0, pixel);
        base *= 1.0 - 0.5 * seen * smoothstep(0.72, 0.8, grain);
        base = mix(base, vec3(0.85), 0.35 * seen * (1.0 - smoothstep(0.18, 0.26, grain)));
        height = 0.15 * mottle + 0.012 * seen * grain;
    } else if (kind == 2) {  // marble: thin dark veins winding through a pale body
        float t = dot(q, vec3(0.35, 0.22, 0.13)) + 2.2 * fbm(q * 0.35, 0.35 * pixel);
        float vein = pow(1.0 - abs(sin(t * 3.14159)), 10.0);
        float fine = pow(1.0 - abs(sin((t + 0.6 * fbm(q * 1.3 + 4.0, 1.3 * pixel)) * 7.3)), 24.0);
        base = mix(base, base * vec3(0.38, 0.40, 0.44), vein + 0.5 * fine * resolved(3.0, pixel));
        base *= 0.95 + 0.08 * fbm(q * 0.8 + 11.0, 0.8 * pixel);
        height = -0.01 * vein;
    } else if (kind == 3) {  // bronze: metal under a green patina, more on faces turned up
        float patina = smoothstep(0.6, 0.82, fbm(q * 0.6, 0.6 * pixel) + 0.2 * n.y);
        float hammer = mix(0.5, noise3(q * 2.0), resolved(2.0, pixel));
        base *= 0.85 + 0.3 * hammer;
        base = mix(base, vec3(0.06, 0.13, 0.1), 0.85 * patina);
        metallic *= 1.0 - patina;
        specular *= 1.0 - 0.8 * patina;
        shininess = mix(shininess, 8.0, patina);
        height = 0.02 * hammer + 0.01 * patina;
    } else if (kind == 4) {  // clay: faint smears of a darker and a lighter body
        float smear = fbm(q * vec3(0.6, 1.4, 0.6), 1.4 * pixel);
        base *= 0.9 + 0.2 * smear;
        height = 0.1 * smear;
    } else if (kind == 5) {  // plaster: a faint fine grain
        float grain = mix(0.5, noise3(q * 14.0), resolved(14.0, pixel));
        base *= 0.97 + 0.06 * grain;
        height = 0.004 * grain;
    } else if (kind == 6) {  // wood: growth rings round the model's vertical axis, fine grain along it
        vec2 warp = vec2(noise3(q * 0.25), noise3(q * 0.25 + 7.0)) - 0.5;
        float r = length(q.xz + 1.6 * warp) * 1.1 + 0.4 * noise3(q * vec3(0.6, 0.08, 0.6));
        float ring = smoothstep(0.55, 0.95, fract(r)) * resolved(1.1, pixel);
        base *= 1.0 - 0.38 * ring;
        float streak = mix(0.5, noise3(q * vec3(18.0, 0.9, 18.0)), resolved(18.0, pixel));
        base *= 0.94 + 0.12 * streak;
        height = -0.02 * ring + 0.004 * streak;
    }
}
)";

// The surface's form from screen-space derivatives: relief and cavity.
const char* const kMeshFormGlsl = R"(
// The shading normal tilted by the gradient of a height field h over the
// surface (world units), from screen-space derivatives of h and of the
// position: Mikkelsen's surface gradient ("Bump Mapping Unparametrized
// Surfaces on the GPU", 2010), so no tangents are needed on our meshes.
vec3 bumped(vec3 n, vec3 p, float h) {
    vec3 dpx = dFdx(p), dpy = dFdy(p);
    vec3 r1 = cross(dpy, n), r2 = cross(n, dpx);
    float det = dot(dpx, r1);
    if (abs(det) < 1e-20) return n;
    vec3 gradient = sign(det) * (dFdx(h) * r1 + dFdy(h) * r2);
    return normalize(abs(det) * n - gradient);
}
// Cavity shading (the clay view): the surface's curvature from how the
// normal turns across the pixel, along each screen axis (positive where
// the surface bends away, a ridge; negative in a groove), measured against
// kCavityPixels pixels of surface, so a groove a few pixels across reads
// fully at any distance, as in sculpting programs. A factor on the colour:
// grooves down to 0.4, ridges up to 1.3 (linear light).
const float kCavityPixels = 8.0;
float cavityFactor(vec3 n, vec3 p, float strength) {
    vec3 dpx = dFdx(p), dpy = dFdy(p);
    float px = dot(dpx, dpx), py = dot(dpy, dpy);
    if (px < 1e-20 || py < 1e-20) return 1.0;
    float bend = dot(dFdx(n), dpx) / px + dot(dFdy(n), dpy) / py;  // about 2 / radius
    float pixel = 0.5 * (sqrt(px) + sqrt(py));
    float c = clamp(0.5 * bend * kCavityPixels * pixel, -1.0, 1.0);
    return 1.0 + strength * (c < 0.0 ? 0.6 * c : 0.3 * c);
}
)";

const char* const kMeshVertex = "#version 330 core\n" HG_SRGB_GLSL HG_DRAW_RECORD_GLSL R"(
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in uint aDraw;
uniform mat4 uViewProjection;
out vec3 vWorld;
out vec3 vNormal;
out vec3 vModel;  // the materials' detail is a function of the model-space position
// The draw's material, the same over the whole draw: read and decoded here,
// once a vertex, rather than once a pixel (a software renderer pays the
// texel fetches and the sRGB decode's pow for every fragment).
flat out vec4 vSurface;  // linear base colour, specular strength
flat out vec4 vFinish;   // shininess, has normals, cavity
flat out vec4 vDetail;   // SurfaceKind, metallic, detail scale
flat out float vModelScale;  // the model matrix's scale: model units to metres
void main() {
    int draw = int(aDraw);
    mat4 model = drawModel(draw);
    vec4 world = model * vec4(aPosition, 1.0);
    vWorld = world.xyz;
    vModel = aPosition;
    vNormal = drawNormalMatrix(draw) * aNormal;
    vec4 surface = drawRecord(draw, 7);  // sRGB base colour, specular
    vSurface = vec4(toLinear(surface.rgb), surface.a);
    vFinish = drawRecord(draw, 8);
    vDetail = drawRecord(draw, 9);
    vModelScale = length(model[0].xyz);
    gl_Position = uViewProjection * world;
}
)";

const char* const kMeshFragmentHead = "#version 330 core\n" HG_LIGHTING_GLSL R"(
in vec3 vWorld;
in vec3 vNormal;
in vec3 vModel;
flat in vec4 vSurface;
flat in vec4 vFinish;
flat in vec4 vDetail;
flat in float vModelScale;
uniform float uBump;  // 1: the detail's relief tilts the shading normal (RenderQuality::materialBump)
layout(location = 0) out vec4 fragColor;
#ifdef HG_BAKE
// An impostor's view (impostor_atlas.h): the surface's colour before
// lighting, and its model-space normal and depth along the view, in
// reaches (the view's half-width) from the centre.
layout(location = 1) out vec4 bakeNormalDepth;
uniform vec3 uBakeCentre;
uniform vec3 uBakeToViewer;
uniform float uBakeReach;
#endif
)";
const char* const kMeshFragmentMain = R"(void main() {
    // Without vertex normals, the face normal from screen-space derivatives
    // (it faces the viewer, and culling leaves only front faces).
    vec4 finish = vFinish;
    vec4 detail = vDetail;  // SurfaceKind (this program is its kind's: HG_KIND), metallic, detail scale
    vec3 n = finish.y > 0.5 ? normalize(vNormal) : normalize(cross(dFdx(vWorld), dFdy(vWorld)));
    vec3 base = vSurface.rgb;
    vec3 specular = vec3(vSurface.a);
    float shininess = finish.x, metallic = detail.y;
    // Each kind has its own program (HG_KIND, Renderer::meshProgram): the
    // branches of the others' detail are compiled out, and the plain
    // material pays for none.
    const int kind = HG_KIND;
    if (kind != 0) {
        vec3 q = vModel / detail.z;
        float pixel = max(length(fwidth(q)), 1e-6);
        float height;
        surfaceDetail(kind, q, n, pixel, base, specular, shininess, metallic, height);
        // The relief in world units: pattern units to model units to metres.
        if (uBump > 0.0)
            n = bumped(n, vWorld, uBump * height * detail.z * vModelScale);
    }
    // (A draw's cavity is the same over a triangle: derivatives defined.)
    if (finish.z > 0.0) base *= cavityFactor(n, vWorld, finish.z);
#ifdef HG_BAKE
    fragColor = vec4(base, 1.0);
    bakeNormalDepth = vec4(n, dot(vModel - uBakeCentre, uBakeToViewer) / uBakeReach);
    return;
#endif
    // A metal's highlight is its own colour and strong; its diffuse light
    // fades (Blinn-Phong's stand-in for a metal's missing diffuse term).
    specular = mix(specular, base * (0.6 + specular), metallic);
    fragColor = aerial(shade(base * (1.0 - 0.6 * metallic), n, vWorld, specular, shininess), vWorld);
}
)";

const char* meshFragment() {
    static const std::string source = std::string(kMeshFragmentHead) + kSurfaceDetailGlsl + kMeshFormGlsl + kMeshFragmentMain;
    return source.c_str();
}

const char* const kGroundVertex = R"(#version 330 core
layout(location = 0) in vec3 aPosition;
uniform mat4 uViewProjection;
out vec3 vWorld;
void main() {
    vWorld = aPosition;
    gl_Position = uViewProjection * vec4(aPosition, 1.0);
}
)";

const char* const kGroundFragment = "#version 330 core\n" HG_LIGHTING_GLSL HG_VALUE_NOISE_2D_GLSL R"(
in vec3 vWorld;
uniform vec3 uGroundColor;
uniform vec3 uLineColor;
uniform float uSpacing;
uniform float uLineWidth;   // pixels
uniform int uMajorEvery;
uniform vec2 uGardenHalfExtent;   // the mown garden: |x|, |z| within it; 0: all of it
uniform float uGridReach;         // metres from the eye the grid shows whole; 0: everywhere
uniform float uStripeWidth;       // metres a mown stripe; 0: none
out vec4 fragColor;
// Value noise (above) in world space: the lawn looks the same from anywhere.
// Lawn: patches a few metres and under a metre across, and tufts of a few
// centimetres that fade to their mean where they shrink below a pixel.
float lawn(vec2 p) {
    float n = 0.55 * noise(p / 3.1) + 0.3 * noise(p / 0.7 + 17.0);
    float w = max(fwidth(p.x), fwidth(p.y));
    n += 0.15 * mix(noise(p / 0.035 + 3.0), 0.5, smoothstep(0.01, 0.03, w));
    return n;
}
// Blades seen close: centimetre tufts and the shade between them, -1..1,
// streaked along z, the way the mower laid them (the stripes' lean); 0
// where they shrink below a pixel, so nothing shimmers.
float blades(vec2 p) {
    float w = max(fwidth(p.x), fwidth(p.y));
    float seen = 1.0 - smoothstep(0.004, 0.012, w);
    if (seen <= 0.0) return 0.0;
    float b = 0.6 * noise(p / vec2(0.008, 0.035)) + 0.4 * noise(p / vec2(0.004, 0.015) + 5.0);
    return seen * (2.0 * b - 1.0);
}
// 1 on a line of the grid with the given spacing, 0 between, anti-aliased
// over a pixel; fades out where cells shrink to a few pixels (no moire).
float grid(vec2 coord, float width) {
    vec2 w = max(fwidth(coord), vec2(1e-6));
    vec2 d = abs(fract(coord - 0.5) - 0.5) / w;
    float line = 1.0 - smoothstep(0.5 * width - 0.5, 0.5 * width + 0.5, min(d.x, d.y));
    return line * (1.0 - smoothstep(0.15, 0.35, max(w.x, w.y)));
}
// Mown stripes: alternate bands of constant x whose blades lean towards +z
// and -z, so a band is lighter seen along its lean and darker against it,
// and the stripes swap as the visitor turns. -1..1, anti-aliased at the
// band edges, gone where a band shrinks to a pixel or two.
float mownStripe(vec2 p) {
    if (uStripeWidth <= 0.0) return 0.0;
    float t = p.x / uStripeWidth;
    float ft = max(fwidth(t), 1e-6);
    float triangle = abs(fract(0.5 * t) - 0.5) * 4.0 - 1.0;  // +-1 at band centres
    float band = clamp(triangle / max(2.0 * ft, 0.04), -1.0, 1.0);
    vec3 toEye = uEye - vWorld;
    float along = toEye.z / max(length(toEye), 1e-4);
    return band * along * (1.0 - smoothstep(0.25, 0.5, ft));
}
void main() {
    // 1 inside the garden's mown lawn, 0 in the meadow beyond, over a few
    // centimetres (a pixel or more).
    float garden = 1.0;
    if (uGardenHalfExtent.x > 0.0 && uGardenHalfExtent.y > 0.0) {
        vec2 inside = uGardenHalfExtent - abs(vWorld.xz);
        float edge = max(max(fwidth(vWorld.x), fwidth(vWorld.z)), 0.05);
        garden = smoothstep(-edge, edge, min(inside.x, inside.y));
    }
    vec2 coord = vWorld.xz / uSpacing;
    float line = grid(coord, uLineWidth);
    if (uMajorEvery > 1) line = max(line, grid(coord / float(uMajorEvery), 2.0 * uLineWidth));
    // The grid is for scale near the visitor, not a pattern to the horizon.
    if (uGridReach > 0.0) line *= 1.0 - smoothstep(uGridReach, 2.0 * uGridReach, length(vWorld - uEye));
    line *= garden;
    float n = lawn(vWorld.xz);
    // Lighter, yellower where the grass is dry; darker and greener where lush.
    vec3 grass = toLinear(uGroundColor) * (0.7 + 0.6 * n) * mix(vec3(1.0), vec3(1.12, 1.06, 0.78), smoothstep(0.55, 0.8, n));
    // Close by: lit blade tips a little yellower, the shade between them deeper.
    float blade = blades(vWorld.xz);
    grass *= (1.0 + 0.35 * blade) * mix(vec3(1.0), vec3(1.08, 1.04, 0.8), max(blade, 0.0));
    // The meadow beyond the garden is longer grass: darker, a little dry.
    vec3 meadow = grass * vec3(0.82, 0.84, 0.72);
    grass = mix(meadow, grass * (1.0 + 0.1 * mownStripe(vWorld.xz)), garden);
    vec3 base = mix(grass, toLinear(uLineColor), line);
    fragColor = aerial(shade(base, vec3(0.0, 1.0, 0.0), vWorld, vec3(0.0), 1.0), vWorld);
}
)";

const char* const kFullscreenVertex = R"(#version 330 core
// One triangle covering the viewport, from gl_VertexID alone.
out vec2 vUv;
void main() {
    vUv = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
    gl_Position = vec4(vUv * 2.0 - 1.0, 0.0, 1.0);
}
)";

const char* const kFlatVertex = R"(#version 330 core
layout(location = 0) in vec3 aPosition;
uniform mat4 uModel;
uniform mat4 uView;
uniform mat4 uProjection;
uniform float uDepthPull;
void main() {
    vec4 eye = uView * uModel * vec4(aPosition, 1.0);
    // Scaling about the eye keeps the screen position and moves the depth
    // a fixed fraction of the distance nearer.
    eye.xyz *= 1.0 - uDepthPull;
    gl_Position = uProjection * eye;
}
)";

const char* const kFlatFragment = R"(#version 330 core
uniform vec4 uColor;
out vec4 fragColor;
void main() { fragColor = uColor; }
)";

const char* const kLightingGlsl = HG_LIGHTING_GLSL;

#undef HG_LIGHTING_GLSL

}  // namespace hg::garden::shaders
