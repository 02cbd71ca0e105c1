// Tests of the HyperFun library routines (frep/kernels/library) for V = double:
// hand-computed values for simple inputs, numerical integrals for the
// convolution kernels, in-place rewriting, sentinels, dispatch of every id,
// and replicas of the conformance programs that exercise the library
// (checked row by row against the reference's tables in tests/data).
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <deque>
#include <fstream>
#include <functional>
#include <initializer_list>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "frep/kernels/library/library.h"
#include "frep/kernels/library/library_impl.h"

namespace {

namespace lib = hg::frep::lib;
using Vec = std::vector<double>;

constexpr double kSentinel = lib::kSentinel;
constexpr double kPi = 3.14159265358979323846;

// One argument of a library call: an array (by reference) or a number.
struct Arg {
    Arg(Vec& a) : array(&a) {}  // NOLINT: implicit on purpose
    Arg(double v) : value(v) {}  // NOLINT
    Vec* array = nullptr;
    double value = 0.0;
};

// Calls the routine named `name` (lower case) through findFunction and
// call<double>, checking the argument kinds against the table.
double hf(const std::string& name, std::initializer_list<Arg> args) {
    const int id = lib::findFunction(name);
    if (id < 0) throw std::runtime_error("no library routine " + name);
    const auto& info = lib::functions()[static_cast<size_t>(id)];
    if (info.params.size() != args.size())
        throw std::runtime_error(name + ": wrong number of arguments");
    lib::Args<double> a;
    size_t i = 0;
    for (const Arg& arg : args) {
        const bool isArray = info.params[i] == lib::ParamKind::Array;
        if (isArray != (arg.array != nullptr))
            throw std::runtime_error(name + ": wrong kind of argument " + std::to_string(i + 1));
        a.arrays.push_back(arg.array);
        a.scalars.push_back(arg.value);
        ++i;
    }
    return lib::call<double>(id, a);
}

// Alpha-0 R-functions, as the reference interpreter computes | & \.
double rUnion(double f, double g) { return f + g + std::sqrt(std::fabs(f * f + g * g)); }
double rInter(double f, double g) { return f + g - std::sqrt(std::fabs(f * f + g * g)); }
double rDiff(double f, double g) { return rInter(f, -g); }

double kernel(double s, double r2) {
    const double k = 1.0 + s * s * r2;
    return 1.0 / (k * k);
}

double dist2(const Vec& p, double x, double y, double z) {
    return (p[0] - x) * (p[0] - x) + (p[1] - y) * (p[1] - y) + (p[2] - z) * (p[2] - z);
}

// Midpoint-rule integral of the Cauchy kernel along the segment a-b (per
// unit length).
double segmentIntegral(const Vec& p, const double* a, const double* b, double s, int n = 20000) {
    const double len = std::sqrt((b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]) +
                                 (b[2] - a[2]) * (b[2] - a[2]));
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
        const double t = (i + 0.5) / n;
        sum += kernel(s, dist2(p, a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]),
                               a[2] + t * (b[2] - a[2])));
    }
    return sum * len / n;
}

// Integral of the Cauchy kernel over the triangle a, b, c (per unit area),
// centroid rule on an m x m subdivision.
double triangleIntegral(const Vec& p, const double* a, const double* b, const double* c, double s,
                        int m = 300) {
    const double e1[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double e2[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    const double cr[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                          e1[0] * e2[1] - e1[1] * e2[0]};
    const double area = 0.5 * std::sqrt(cr[0] * cr[0] + cr[1] * cr[1] + cr[2] * cr[2]);
    double sum = 0.0;
    for (int i = 0; i < m; ++i) {
        for (int j = 0; j < m - i; ++j) {
            for (int up = 0; up < 2; ++up) {
                if (up == 1 && i + j + 1 >= m) continue;
                const double u = (i + (up ? 2.0 : 1.0) / 3.0) / m;
                const double w = (j + (up ? 2.0 : 1.0) / 3.0) / m;
                sum += kernel(s, dist2(p, a[0] + u * e1[0] + w * e2[0],
                                       a[1] + u * e1[1] + w * e2[1],
                                       a[2] + u * e1[2] + w * e2[2]));
            }
        }
    }
    return sum * area / (static_cast<double>(m) * m);
}

void expectVec(const Vec& got, const Vec& want, double tol = 1e-12) {
    ASSERT_EQ(got.size(), want.size());
    for (size_t i = 0; i < got.size(); ++i) EXPECT_NEAR(got[i], want[i], tol) << "item " << i;
}

// ---------------------------------------------------------------------------
// Primitives

TEST(LibraryPrimitives, Sphere) {
    Vec c = {1, 2, 3};
    Vec x = {1, 2, 3};
    EXPECT_DOUBLE_EQ(hf("hfsphere", {x, c, 2.0}), 4.0);
    x = {3, 2, 3};
    EXPECT_DOUBLE_EQ(hf("hfsphere", {x, c, 2.0}), 0.0);
    x = {1, 2, 6};
    EXPECT_DOUBLE_EQ(hf("hfsphere", {x, c, 2.0}), -5.0);
    // The point array must have exactly three items.
    Vec flat = {1, 2};
    Vec four = {1, 2, 3, 4};
    EXPECT_EQ(hf("hfsphere", {flat, c, 2.0}), kSentinel);
    EXPECT_EQ(hf("hfsphere", {four, c, 2.0}), kSentinel);
}

TEST(LibraryPrimitives, Ellipsoid) {
    Vec c = {0, 0, 0};
    Vec x = {1, 0, 0};
    EXPECT_DOUBLE_EQ(hf("hfellipsoid", {x, c, 2.0, 1.0, 0.5}), 0.75);
    x = {0, 0, 0.5};
    EXPECT_DOUBLE_EQ(hf("hfellipsoid", {x, c, 2.0, 1.0, 0.5}), 0.0);
    x = {0, 0, 0};
    EXPECT_DOUBLE_EQ(hf("hfellipsoid", {x, c, 2.0, 1.0, 0.5}), 1.0);
    x = {1, 0, 0};
    EXPECT_DOUBLE_EQ(hf("hfellipsoid", {x, c, -2.0, 1.0, 0.5}), 0.75);  // sign is irrelevant
    EXPECT_EQ(hf("hfellipsoid", {x, c, 2.0, 0.0, 0.5}), kSentinel);
    EXPECT_EQ(hf("hfellipsoid", {x, c, 2.0, 1.0, 9e-7}), kSentinel);
    EXPECT_NE(hf("hfellipsoid", {x, c, 2.0, 1.0, 1e-6}), kSentinel);  // |c| < EPS is strict
}

TEST(LibraryPrimitives, Tori) {
    Vec c = {0, 0, 0};
    // Tube centre: r0^2; tube surface: 0.
    Vec x = {2, 0, 0};
    EXPECT_DOUBLE_EQ(hf("hftorusz", {x, c, 2.0, 0.5}), 0.25);
    x = {0, -2, 0};
    EXPECT_DOUBLE_EQ(hf("hftorusz", {x, c, 2.0, 0.5}), 0.25);
    x = {2.5, 0, 0};
    EXPECT_DOUBLE_EQ(hf("hftorusz", {x, c, 2.0, 0.5}), 0.0);
    x = {2, 0, 0.5};
    EXPECT_DOUBLE_EQ(hf("hftorusz", {x, c, 2.0, 0.5}), 0.0);
    x = {0, 0, 0};  // the hole: r0^2 - R^2
    EXPECT_DOUBLE_EQ(hf("hftorusz", {x, c, 2.0, 0.5}), 0.25 - 4.0);

    x = {0, 2, 0};
    EXPECT_DOUBLE_EQ(hf("hftorusx", {x, c, 2.0, 0.5}), 0.25);
    x = {0, 0, 2};
    EXPECT_DOUBLE_EQ(hf("hftorusx", {x, c, 2.0, 0.5}), 0.25);
    x = {0.5, 2, 0};
    EXPECT_DOUBLE_EQ(hf("hftorusx", {x, c, 2.0, 0.5}), 0.0);

    x = {2, 0, 0};
    EXPECT_DOUBLE_EQ(hf("hftorusy", {x, c, 2.0, 0.5}), 0.25);
    x = {0, 0, -2};
    EXPECT_DOUBLE_EQ(hf("hftorusy", {x, c, 2.0, 0.5}), 0.25);
    x = {0, 0.5, 2};
    EXPECT_DOUBLE_EQ(hf("hftorusy", {x, c, 2.0, 0.5}), 0.0);

    // Off-centre torus.
    Vec c2 = {1, 1, 1};
    x = {3, 1, 1};
    EXPECT_DOUBLE_EQ(hf("hftorusz", {x, c2, 2.0, 0.5}), 0.25);
    Vec flat = {1, 1};
    EXPECT_EQ(hf("hftorusy", {flat, c, 2.0, 0.5}), kSentinel);
}

TEST(LibraryPrimitives, EllipticCylinders) {
    Vec c = {0, 0, 0};
    Vec x = {100, 1, 0};
    EXPECT_DOUBLE_EQ(hf("hfellcylx", {x, c, 2.0, 0.5}), 0.75);
    x = {-5, 0, 0.5};
    EXPECT_DOUBLE_EQ(hf("hfellcylx", {x, c, 2.0, 0.5}), 0.0);
    x = {1, 100, 0};
    EXPECT_DOUBLE_EQ(hf("hfellcyly", {x, c, 2.0, 0.5}), 0.75);
    x = {0, 7, 0.5};
    EXPECT_DOUBLE_EQ(hf("hfellcyly", {x, c, 2.0, 0.5}), 0.0);
    x = {1, 0, 100};
    EXPECT_DOUBLE_EQ(hf("hfellcylz", {x, c, 2.0, 0.5}), 0.75);
    x = {0, 0.5, -3};
    EXPECT_DOUBLE_EQ(hf("hfellcylz", {x, c, 2.0, 0.5}), 0.0);
    EXPECT_EQ(hf("hfellcylz", {x, c, 1e-7, 1.0}), kSentinel);
    EXPECT_EQ(hf("hfellcylx", {x, c, 1.0, 0.0}), kSentinel);
    EXPECT_EQ(hf("hfellcyly", {x, c, 0.0, 1.0}), kSentinel);
}

TEST(LibraryPrimitives, Cylinders) {
    Vec c = {0, 1, 0};
    Vec x = {7, 1, 0};
    EXPECT_DOUBLE_EQ(hf("hfcylinderx", {x, c, 1.0}), 1.0);
    x = {3, 1.6, 0.8};
    EXPECT_NEAR(hf("hfcylinderx", {x, c, 1.0}), 0.0, 1e-15);
    x = {0, -9, 0};
    EXPECT_DOUBLE_EQ(hf("hfcylindery", {x, c, 1.0}), 1.0);
    x = {0.6, 5, 0.8};
    EXPECT_NEAR(hf("hfcylindery", {x, c, 1.0}), 0.0, 1e-15);
    x = {0, 1, 42};
    EXPECT_DOUBLE_EQ(hf("hfcylinderz", {x, c, 1.0}), 1.0);
    x = {0, 3, 0};
    EXPECT_DOUBLE_EQ(hf("hfcylinderz", {x, c, 1.0}), -3.0);
}

TEST(LibraryPrimitives, Block) {
    Vec v = {0, 0, 0};
    // Centre: slab products 0.25, 1, 2.25 combined with the alpha-0
    // intersection.
    Vec x = {0.5, 1, 1.5};
    const double f = 0.25 + 1.0 - std::sqrt(0.25 * 0.25 + 1.0);
    const double want = f + 2.25 - std::sqrt(f * f + 2.25 * 2.25);
    EXPECT_DOUBLE_EQ(hf("hfblock", {x, v, 1.0, 2.0, 3.0}), want);
    EXPECT_GT(want, 0.0);
    // On a face: exactly 0.
    x = {0, 1, 1.5};
    EXPECT_DOUBLE_EQ(hf("hfblock", {x, v, 1.0, 2.0, 3.0}), 0.0);
    x = {-1, 1, 1.5};
    EXPECT_LT(hf("hfblock", {x, v, 1.0, 2.0, 3.0}), 0.0);
    x = {0.5, 1, 3.5};
    EXPECT_LT(hf("hfblock", {x, v, 1.0, 2.0, 3.0}), 0.0);
    // A negative edge is degenerate; a zero edge is not.
    EXPECT_EQ(hf("hfblock", {x, v, 1.0, -1.0, 1.0}), kSentinel);
    EXPECT_NE(hf("hfblock", {x, v, 1.0, 0.0, 1.0}), kSentinel);
}

TEST(LibraryPrimitives, Cones) {
    Vec c = {0, 0, 0};
    Vec x = {0.5, 0, 1};
    EXPECT_DOUBLE_EQ(hf("hfconez", {x, c, 0.5}), 0.0);
    x = {0, 0, 2};
    EXPECT_DOUBLE_EQ(hf("hfconez", {x, c, 0.5}), 4.0);
    x = {0, 0.5, -1};  // the cone is double
    EXPECT_DOUBLE_EQ(hf("hfconez", {x, c, 0.5}), 0.0);
    x = {1, 0.5, 0};
    EXPECT_DOUBLE_EQ(hf("hfconex", {x, c, 0.5}), 0.0);
    x = {0, 1, 0.25};
    EXPECT_DOUBLE_EQ(hf("hfconey", {x, c, 0.5}), 0.75);
    // Elliptic cones.
    x = {0.5, 0, 1};
    EXPECT_DOUBLE_EQ(hf("hfellconez", {x, c, 0.5, 2.0}), 0.0);
    x = {0, 2, 1};
    EXPECT_DOUBLE_EQ(hf("hfellconez", {x, c, 0.5, 2.0}), 0.0);
    x = {0, 0, 3};
    EXPECT_DOUBLE_EQ(hf("hfellconez", {x, c, 0.5, 2.0}), 9.0);
    x = {2, 1, 0};
    EXPECT_DOUBLE_EQ(hf("hfellconex", {x, c, 0.5, 2.0}), 0.0);
    x = {0.5, 1, 0};
    EXPECT_DOUBLE_EQ(hf("hfellconey", {x, c, 0.5, 2.0}), 0.0);
    x = {0, 1, 2};
    EXPECT_DOUBLE_EQ(hf("hfellconey", {x, c, 0.5, 2.0}), 0.0);
    Vec flat = {0, 0};
    EXPECT_EQ(hf("hfellconex", {flat, c, 0.5, 2.0}), kSentinel);
    EXPECT_EQ(hf("hfconey", {flat, c, 0.5}), kSentinel);
}

TEST(LibraryPrimitives, Superellipsoid) {
    Vec c = {0, 0, 0};
    // s1 = s2 = 1 is the ellipsoid.
    Vec x = {0.5, 0, 0};
    EXPECT_DOUBLE_EQ(hf("hfsuperell", {x, c, 1.0, 1.0, 1.0, 1.0, 1.0}), 0.75);
    x = {0, 0, 0.5};
    EXPECT_DOUBLE_EQ(hf("hfsuperell", {x, c, 1.0, 1.0, 1.0, 1.0, 1.0}), 0.75);
    x = {1, 0, 0};
    EXPECT_DOUBLE_EQ(hf("hfsuperell", {x, c, 1.0, 1.0, 1.0, 1.0, 1.0}), 0.0);
    // s2 = 2: |u| + |v| in the plane (a diamond); s1 = 2: |w| along z.
    x = {0.25, 0.25, 0};
    EXPECT_NEAR(hf("hfsuperell", {x, c, 1.0, 1.0, 1.0, 2.0, 2.0}), 0.5, 1e-15);
    x = {0, 0, 0.5};
    EXPECT_NEAR(hf("hfsuperell", {x, c, 1.0, 1.0, 1.0, 2.0, 2.0}), 0.5, 1e-15);
    // Degenerate exponents and axes.
    EXPECT_EQ(hf("hfsuperell", {x, c, 1.0, 1.0, 1.0, 0.0, 1.0}), kSentinel);
    EXPECT_EQ(hf("hfsuperell", {x, c, 1.0, 1.0, 1.0, 1.0, 5e-7}), kSentinel);
    EXPECT_EQ(hf("hfsuperell", {x, c, 1.0, 0.0, 1.0, 1.0, 1.0}), kSentinel);
}

// ---------------------------------------------------------------------------
// Skeletal primitives

TEST(LibrarySkeletal, Blobby) {
    Vec x = {0, 0, 0};
    Vec cx = {0}, cy = {0}, cz = {0}, a = {1}, b = {2};
    EXPECT_DOUBLE_EQ(hf("hfblobby", {x, cx, cy, cz, a, b, 0.5}), 1.5);
    x = {0, 1, 0};
    EXPECT_DOUBLE_EQ(hf("hfblobby", {x, cx, cy, cz, a, b, 0.5}), 2.0 * std::exp(-1.0) - 0.5);
    // Two centres: contributions add.
    Vec cx2 = {0, 2}, cy2 = {0, 0}, cz2 = {0, 0}, a2 = {1, 3}, b2 = {2, 1};
    x = {1, 0, 0};
    EXPECT_NEAR(hf("hfblobby", {x, cx2, cy2, cz2, a2, b2, 0.0}),
                2.0 * std::exp(-1.0) + std::exp(-3.0), 1e-15);
    // The count comes from the first coordinate array: the extra items of
    // the others are not read.
    Vec longer = {0, 0, 5, 5};
    EXPECT_NEAR(hf("hfblobby", {x, cx2, longer, longer, a2, b2, 0.0}),
                2.0 * std::exp(-1.0) + std::exp(-3.0), 1e-15);
    // Shorter parameter arrays would be read past their end: sentinel.
    Vec one = {0};
    EXPECT_EQ(hf("hfblobby", {x, cx2, one, cz2, a2, b2, 0.0}), kSentinel);
}

TEST(LibrarySkeletal, Metaball) {
    Vec cx = {0}, cy = {0}, cz = {0}, b = {1}, d = {3};
    Vec x = {0, 0, 0};
    EXPECT_DOUBLE_EQ(hf("hfmetaball", {x, cx, cy, cz, b, d, 0.1}), 0.9);
    x = {1, 0, 0};  // r = d/3: 1 - 3 (1/3)^2
    EXPECT_NEAR(hf("hfmetaball", {x, cx, cy, cz, b, d, 0.0}), 2.0 / 3.0, 1e-15);
    x = {0, 2, 0};  // 1.5 (1 - 2/3)^2
    EXPECT_NEAR(hf("hfmetaball", {x, cx, cy, cz, b, d, 0.0}), 1.0 / 6.0, 1e-15);
    x = {0, 0, 3};  // at the reach: nothing
    EXPECT_DOUBLE_EQ(hf("hfmetaball", {x, cx, cy, cz, b, d, 0.1}), -0.1);
    x = {0, 0, 5};
    EXPECT_DOUBLE_EQ(hf("hfmetaball", {x, cx, cy, cz, b, d, 0.1}), -0.1);
    // A centre whose reach is not positive is ignored.
    Vec dneg = {-1}, dzero = {0};
    x = {0, 0, 0};
    EXPECT_DOUBLE_EQ(hf("hfmetaball", {x, cx, cy, cz, b, dneg, 0.1}), -0.1);
    EXPECT_DOUBLE_EQ(hf("hfmetaball", {x, cx, cy, cz, b, dzero, 0.1}), -0.1);
}

TEST(LibrarySkeletal, Soft) {
    Vec cx = {0}, cy = {0}, cz = {0}, d = {1};
    Vec x = {0, 0, 0};
    EXPECT_DOUBLE_EQ(hf("hfsoft", {x, cx, cy, cz, d, 0.25}), 0.75);
    x = {0.5, 0, 0};  // 1 - 22/36 + 17/144 - 4/576 = 0.5
    EXPECT_NEAR(hf("hfsoft", {x, cx, cy, cz, d, 0.0}), 0.5, 1e-15);
    x = {0, 1, 0};  // at the reach the kernel is 0
    EXPECT_NEAR(hf("hfsoft", {x, cx, cy, cz, d, 0.0}), 0.0, 1e-15);
    x = {0, 0, 2};
    EXPECT_DOUBLE_EQ(hf("hfsoft", {x, cx, cy, cz, d, 0.25}), -0.25);
}

// ---------------------------------------------------------------------------
// Transformations

TEST(LibraryTransforms, ShiftAndScale) {
    Vec p = {1, 2, 3};
    EXPECT_EQ(hf("hfshift3d", {p, 0.5, 1.0, -1.0}), 1.0);
    expectVec(p, {0.5, 1, 4}, 0.0);
    EXPECT_EQ(hf("hfscale3d", {p, 0.5, 2.0, 4.0}), 1.0);
    expectVec(p, {1, 0.5, 1}, 0.0);
    // A shifted sphere: the sphere at the origin sampled at the shifted
    // point is a sphere centred at the shift.
    Vec o = {0, 0, 0};
    Vec q = {2, 3, 4};
    hf("hfshift3d", {q, 2.0, 3.0, 4.0});
    EXPECT_DOUBLE_EQ(hf("hfsphere", {q, o, 1.0}), 1.0);
    // Arrays longer than 3 keep their other items.
    Vec longer = {1, 1, 1, 7};
    hf("hfshift3d", {longer, 1.0, 1.0, 1.0});
    expectVec(longer, {0, 0, 0, 7}, 0.0);
    Vec shortArr = {1, 2};
    EXPECT_EQ(hf("hfshift3d", {shortArr, 1.0, 1.0, 1.0}), kSentinel);
    expectVec(shortArr, {1, 2}, 0.0);
}

TEST(LibraryTransforms, RotateQuarterTurn) {
    const double h = kPi / 2;
    Vec p = {1, 2, 3};
    EXPECT_EQ(hf("hfrotate3dz", {p, h}), 1.0);
    expectVec(p, {2, -1, 3});
    p = {1, 2, 3};
    EXPECT_EQ(hf("hfrotate3dy", {p, h}), 1.0);
    expectVec(p, {-3, 2, 1});
    p = {1, 2, 3};
    EXPECT_EQ(hf("hfrotate3dx", {p, h}), 1.0);
    expectVec(p, {1, 3, -2});
    // Four quarter turns come back.
    p = {0.3, -0.7, 1.1};
    for (int i = 0; i < 4; ++i) hf("hfrotate3dz", {p, h});
    expectVec(p, {0.3, -0.7, 1.1});
}

TEST(LibraryTransforms, Twist) {
    // Angle 0 at z = 0 and pi/2 at z = 1.
    Vec p = {1, 0, 1};
    EXPECT_EQ(hf("hftwistz", {p, 0.0, 1.0, 0.0, kPi / 2}), 1.0);
    expectVec(p, {0, -1, 1});
    p = {1, 0, 0};
    hf("hftwistz", {p, 0.0, 1.0, 0.0, kPi / 2});
    expectVec(p, {1, 0, 0});
    p = {1, 0, 0.5};
    hf("hftwistz", {p, 0.0, 1.0, 0.0, kPi / 2});
    expectVec(p, {std::sqrt(0.5), -std::sqrt(0.5), 0.5});
    // Extrapolated beyond the interval: z = 2 turns by pi.
    p = {1, 0, 2};
    hf("hftwistz", {p, 0.0, 1.0, 0.0, kPi / 2});
    expectVec(p, {-1, 0, 2});
    // Y and X twists at the end of their intervals equal the rotations.
    p = {1, 1, 3};
    Vec r = p;
    hf("hftwisty", {p, -1.0, 1.0, 0.0, 0.8});
    hf("hfrotate3dy", {r, 0.8});
    expectVec(p, r);
    p = {1, 2, 3};
    r = p;
    hf("hftwistx", {p, 0.0, 1.0, 0.0, -0.3});
    hf("hfrotate3dx", {r, -0.3});
    expectVec(p, r);
}

TEST(LibraryTransforms, Taper) {
    // Scale 1 at z <= 0, 2 at z >= 1, linear in between.
    Vec p = {1, 1, 1};
    EXPECT_EQ(hf("hftaperz", {p, 0.0, 1.0, 1.0, 2.0}), 1.0);
    expectVec(p, {0.5, 0.5, 1});
    p = {3, 3, 0.5};
    hf("hftaperz", {p, 0.0, 1.0, 1.0, 2.0});
    expectVec(p, {2, 2, 0.5});
    p = {3, 3, -5};
    hf("hftaperz", {p, 0.0, 1.0, 1.0, 2.0});
    expectVec(p, {3, 3, -5});
    p = {3, 3, 5};
    hf("hftaperz", {p, 0.0, 1.0, 1.0, 2.0});
    expectVec(p, {1.5, 1.5, 5});
    // A scale below EPS in magnitude counts as 1; negative scales are kept.
    p = {3, 3, 5};
    hf("hftaperz", {p, 0.0, 1.0, 1.0, 0.0});
    expectVec(p, {3, 3, 5});
    p = {3, 3, 5};
    hf("hftaperz", {p, 0.0, 1.0, 1.0, -2.0});
    expectVec(p, {-1.5, -1.5, 5});
    // Y and X tapers scale the two other coordinates.
    p = {2, 1, 2};
    hf("hftapery", {p, 0.0, 1.0, 1.0, 4.0});
    expectVec(p, {0.5, 1, 0.5});
    p = {1, 2, 2};
    hf("hftaperx", {p, 0.0, 1.0, 1.0, 4.0});
    expectVec(p, {1, 0.5, 0.5});
}

TEST(LibraryTransforms, Stretch) {
    Vec anchor = {1, 1, 1};
    Vec p = {3, 1, -1};
    EXPECT_EQ(hf("hfstretch3d", {p, anchor, 2.0, 3.0, 4.0}), 1.0);
    expectVec(p, {2, 1, 0.5}, 0.0);
    expectVec(anchor, {1, 1, 1}, 0.0);
    // The anchor may be the point array itself: nothing moves.
    p = {0.3, 0.4, 0.5};
    hf("hfstretch3d", {p, p, 2.0, 3.0, 4.0});
    expectVec(p, {0.3, 0.4, 0.5}, 0.0);
}

TEST(LibraryTransforms, SpaceMaps) {
    Vec src = {0, 0, 0}, dst = {1, 0, 0}, ratio = {1, 1, 1};
    // The target point is pulled back to the source (weight 1 there).
    Vec p = {1, 0, 0};
    EXPECT_EQ(hf("hfspacemapcubic", {p, src, dst, ratio}), 1.0);
    expectVec(p, {0, 0, 0}, 0.0);
    p = {1, 0, 0};
    EXPECT_EQ(hf("hfspacemapexp", {p, src, dst, ratio}), 1.0);
    expectVec(p, {0, 0, 0}, 0.0);
    // Cubic: no effect beyond the influence radius (ratio * (1 + |d|) = 2).
    p = {10, 0, 0};
    hf("hfspacemapcubic", {p, src, dst, ratio});
    expectVec(p, {10, 0, 0}, 0.0);
    // Half way to the edge: r = 0.5, weight 0.125 / 1.5.
    p = {2, 0, 0};
    hf("hfspacemapcubic", {p, src, dst, ratio});
    expectVec(p, {2 - 0.125 / 1.5, 0, 0});
    // Exponential: weight exp(-r^2), r = 4.5.
    p = {10, 0, 0};
    hf("hfspacemapexp", {p, src, dst, ratio});
    expectVec(p, {10 - std::exp(-20.25), 0, 0});
    // Two mappings apply in turn.
    Vec src2 = {0, 0, 0, 5, 5, 5}, dst2 = {1, 0, 0, 5, 6, 5}, ratio2 = {1, 1, 1, 1, 1, 1};
    p = {1, 0, 0};
    hf("hfspacemapcubic", {p, src2, dst2, ratio2});
    expectVec(p, {0, 0, 0}, 0.0);
    // Source array not a whole number of points: sentinel, point unchanged.
    Vec bad = {0, 0, 0, 1};
    p = {1, 0, 0};
    EXPECT_EQ(hf("hfspacemapexp", {p, bad, dst2, ratio2}), kSentinel);
    expectVec(p, {1, 0, 0}, 0.0);
}

// ---------------------------------------------------------------------------
// Blends and noise

TEST(LibraryBlends, UnionAndIntersection) {
    EXPECT_DOUBLE_EQ(hf("hfblenduni", {0.0, 0.0, 1.0, 1.0, 1.0}), 1.0);
    EXPECT_DOUBLE_EQ(hf("hfblenduni", {3.0, 4.0, 0.0, 1.0, 1.0}), 12.0);
    EXPECT_DOUBLE_EQ(hf("hfblendint", {3.0, 4.0, 0.0, 1.0, 1.0}), 2.0);
    EXPECT_DOUBLE_EQ(hf("hfblenduni", {1.0, 0.0, 2.0, 1.0, 1.0}), 3.0);
    EXPECT_DOUBLE_EQ(hf("hfblendint", {-1.0, 0.0, 2.0, 1.0, 5.0}), -1.0 - 1.0 + 1.0);
    // The displacement fades with the two values, scaled by a1 and a2.
    EXPECT_DOUBLE_EQ(hf("hfblenduni", {2.0, 0.0, 3.0, 2.0, 1.0}), 2.0 + 2.0 + 1.5);
    EXPECT_DOUBLE_EQ(hf("hfblendint", {0.0, 2.0, 3.0, 1.0, 2.0}), 1.5);
}

TEST(LibraryNoise, GardnerSeries) {
    Vec x = {0, 0, 0};
    EXPECT_DOUBLE_EQ(hf("hfnoiseg", {x, 2.0, 1.0, 1.4}), 0.0);
    // phase 0: each factor is amp (sin(f x) + sin(f x / 1.35) / 1.17).
    x = {kPi / 2, kPi / 2, kPi / 2};
    const double s = 1.0 + std::sin(kPi / 2 / 1.35) / 1.17;
    EXPECT_NEAR(hf("hfnoiseg", {x, 1.0, 1.0, 0.0}), s * s * s, 1e-14);
    x = {kPi / 4, kPi / 4, kPi / 4};
    EXPECT_NEAR(hf("hfnoiseg", {x, 2.0, 2.0, 0.0}), 8.0 * s * s * s, 1e-13);
    Vec flat = {1, 1};
    EXPECT_EQ(hf("hfnoiseg", {flat, 1.0, 1.0, 1.0}), kSentinel);
}

// ---------------------------------------------------------------------------
// Convolution surfaces

TEST(LibraryConvolution, Point) {
    Vec pts = {0, 0, 0};
    Vec w = {1};
    Vec x = {0, 0, 0};
    EXPECT_DOUBLE_EQ(hf("hfconvpoint", {x, pts, w, 0.0}), 1.0);
    x = {0, 1, 0};
    EXPECT_DOUBLE_EQ(hf("hfconvpoint", {x, pts, w, 0.0}), 0.25);
    x = {0, 0, 2};
    Vec w2 = {0.5};
    EXPECT_DOUBLE_EQ(hf("hfconvpoint", {x, pts, w2, 0.1}), 0.25 - 0.1);
    // Two points, the midpoint is symmetric.
    Vec two = {-1, 0, 0, 1, 0, 0};
    Vec ww = {1, 1};
    x = {0, 0, 0};
    EXPECT_DOUBLE_EQ(hf("hfconvpoint", {x, two, ww, 0.0}), 0.5);
    Vec flat = {0, 0};
    EXPECT_EQ(hf("hfconvpoint", {flat, two, ww, 0.0}), kSentinel);
}

TEST(LibraryConvolution, LineMatchesIntegral) {
    Vec b = {-1, 0.2, 0, 0, 0, 0}, e = {1.5, 0.2, 0.4, 0, 1, 1};
    Vec w = {1.3, 0.7};
    Vec x = {0.9, 1.1, 0.1};
    const double want = segmentIntegral(x, &b[0], &e[0], 1.3) + segmentIntegral(x, &b[3], &e[3], 0.7);
    EXPECT_NEAR(hf("hfconvline", {x, b, e, w, 0.25}), want - 0.25, 1e-8);
    // Symmetric: the field is the same on either side of the mid-plane.
    Vec b1 = {-1, 0, 0}, e1 = {1, 0, 0}, w1 = {2};
    Vec p = {0.3, 0.4, 0.1}, q = {-0.3, 0.4, 0.1};
    EXPECT_NEAR(hf("hfconvline", {p, b1, e1, w1, 0.0}), hf("hfconvline", {q, b1, e1, w1, 0.0}),
                1e-14);
    // Reversing a segment does not change its field.
    EXPECT_NEAR(hf("hfconvline", {p, b1, e1, w1, 0.0}), hf("hfconvline", {p, e1, b1, w1, 0.0}),
                1e-14);
}

TEST(LibraryConvolution, CurveIsChainOfLines) {
    Vec path = {-1.5, 0, 0, -0.5, 0.6, 0.1, 0.4, -0.2, 0.3};
    Vec w = {3, 2};
    Vec b = {-1.5, 0, 0, -0.5, 0.6, 0.1}, e = {-0.5, 0.6, 0.1, 0.4, -0.2, 0.3};
    Vec x = {0.1, 0.2, 0.3};
    EXPECT_DOUBLE_EQ(hf("hfconvcurve", {x, path, w, 0.4}), hf("hfconvline", {x, b, e, w, 0.4}));
    // One more vertex than widths is needed.
    Vec w3 = {3, 2, 1};
    EXPECT_EQ(hf("hfconvcurve", {x, path, w3, 0.4}), kSentinel);
}

TEST(LibraryConvolution, ArcMatchesIntegral) {
    // The arc field is the kernel integrated over the arc's angle (not its
    // length), counterclockwise about the axis from `angle`.
    for (double s : {0.7, 1.3, 3.0}) {
        Vec c = {0.2, 0.1, -0.3}, rad = {1.7}, span = {100}, axis = {0, 0, 1}, turn = {10};
        Vec w = {s};
        Vec x = {0.9, 1.1, 0.1};
        const double v = hf("hfconvarc", {x, c, rad, span, axis, turn, w, 0.0});
        const int n = 20000;
        const double a0 = 10 * kPi / 180, a1 = 110 * kPi / 180;
        double sum = 0.0;
        for (int i = 0; i < n; ++i) {
            const double t = a0 + (a1 - a0) * (i + 0.5) / n;
            sum += kernel(s, dist2(x, c[0] + 1.7 * std::cos(t), c[1] + 1.7 * std::sin(t), c[2]));
        }
        sum *= (a1 - a0) / n;
        EXPECT_NEAR(v, sum, 1e-6 * sum) << "s = " << s;
    }
    // More than half a turn, turned by 90 degrees about the x axis: the arc
    // of the xy plane rotated to (cos t, 0, sin t).
    Vec c = {0, 0, 0}, rad = {1}, span = {270}, axis = {1, 0, 0}, turn = {90}, w = {2};
    Vec x = {0.2, 0.3, -0.8};
    const double v = hf("hfconvarc", {x, c, rad, span, axis, turn, w, 0.0});
    const int n = 40000;
    const double a1 = 270 * kPi / 180;
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
        const double t = a1 * (i + 0.5) / n;
        sum += kernel(2, dist2(x, std::cos(t), 0, std::sin(t)));
    }
    sum *= a1 / n;
    EXPECT_NEAR(v, sum, 1e-5 * sum);
}

TEST(LibraryConvolution, ArcRewritesItsInputs) {
    Vec c = {0, 0, 0, 0.5, 0.5, 0.3, -0.4, 0.2, -0.3};
    Vec rad = {1, 0.6, 0.8};
    Vec span = {120, 270, 400};
    Vec axis = {0, 0, 1, 1, 0, 0, 0.3, 0.5, 0.8};
    Vec turn = {30, 0, 45};
    Vec w = {3, 4, 2.5};
    Vec x = {0.2, 0.4, 0.1};
    const double first = hf("hfconvarc", {x, c, rad, span, axis, turn, w, 0.5});
    // Angles grow by EPS; spans above 180 are clipped to 180 (400 via 360).
    expectVec(turn, {30 + 1e-6, 1e-6, 45 + 1e-6}, 0.0);
    expectVec(span, {120, 180, 180}, 0.0);
    expectVec(axis, {0, 0, 1, 1, 0, 0, 0.3, 0.5, 0.8}, 0.0);  // the axes are not written
    const double second = hf("hfconvarc", {x, c, rad, span, axis, turn, w, 0.5});
    expectVec(turn, {30 + 2e-6, 2e-6, 45 + 2e-6}, 1e-12);
    expectVec(span, {120, 180, 180}, 0.0);
    EXPECT_NE(first, second);
    EXPECT_GT(first, second);  // the clipped arcs contribute less
    Vec flat = {0, 0};
    EXPECT_EQ(hf("hfconvarc", {flat, c, rad, span, axis, turn, w, 0.5}), kSentinel);
}

TEST(LibraryConvolution, TriangleMatchesIntegral) {
    // The triangle field is s^3 times the kernel integrated over the area.
    Vec tri = {0, 0, 0, 1.2, 0, 0, 0.3, 1, 0, 0, 0, 0, 0.3, 1, 0, -0.2, 0.4, 0.9};
    for (double s : {0.7, 2.5}) {
        Vec w = {s, s};
        Vec x = {0.4, 0.3, 0.5};
        const double want = s * s * s *
                            (triangleIntegral(x, &tri[0], &tri[3], &tri[6], s) +
                             triangleIntegral(x, &tri[9], &tri[12], &tri[15], s));
        EXPECT_NEAR(hf("hfconvtriangle", {x, tri, w, 0.0}), want, 2e-5 * want) << "s = " << s;
    }
    // The order of the vertices does not matter.
    Vec t1 = {0, 0, 0, 1.2, 0, 0, 0.3, 1, 0}, t2 = {0.3, 1, 0, 0, 0, 0, 1.2, 0, 0};
    Vec t3 = {1.2, 0, 0, 0.3, 1, 0, 0, 0, 0};
    Vec w = {2};
    Vec x = {0.5, 0.2, -0.3};
    const double v1 = hf("hfconvtriangle", {x, t1, w, 0.0});
    EXPECT_NEAR(hf("hfconvtriangle", {x, t2, w, 0.0}), v1, 1e-12);
    EXPECT_NEAR(hf("hfconvtriangle", {x, t3, w, 0.0}), v1, 1e-12);
    Vec flat = {0, 0};
    EXPECT_EQ(hf("hfconvtriangle", {flat, t1, w, 0.0}), kSentinel);
}

TEST(LibraryConvolution, MeshIsListOfTriangles) {
    Vec vert = {0, 0, 0, 1, 0, 0, 0.5, 0.9, 0, 0.5, 0.3, 0.8};
    Vec faces = {1, 2, 3, 1, 2, 4, 2, 3, 4, 3, 1, 4};
    Vec w = {3, 3, 3.5, 2.5};
    Vec tris = {0, 0, 0, 1, 0, 0, 0.5, 0.9, 0,        //
                0, 0, 0, 1, 0, 0, 0.5, 0.3, 0.8,      //
                1, 0, 0, 0.5, 0.9, 0, 0.5, 0.3, 0.8,  //
                0.5, 0.9, 0, 0, 0, 0, 0.5, 0.3, 0.8};
    Vec x = {0.4, 0.3, 0.2};
    double mesh = 0.0;
    EXPECT_NO_THROW(mesh = hf("hfconvmesh", {x, vert, faces, w, 0.7}));  // no NotCompilable
    EXPECT_DOUBLE_EQ(mesh, hf("hfconvtriangle", {x, tris, w, 0.7}));
    // Indices are truncated toward zero, like the reference's (int) cast.
    Vec facesFrac = {1.9, 2.2, 3.99, 1, 2, 4, 2, 3, 4, 3, 1, 4};
    EXPECT_DOUBLE_EQ(hf("hfconvmesh", {x, vert, facesFrac, w, 0.7}), mesh);
    // An index outside the vertex list gives the sentinel.
    Vec facesBad = {1, 2, 5, 1, 2, 4, 2, 3, 4, 3, 1, 4};
    EXPECT_EQ(hf("hfconvmesh", {x, vert, facesBad, w, 0.7}), kSentinel);
    Vec facesZero = {0, 2, 3, 1, 2, 4, 2, 3, 4, 3, 1, 4};
    EXPECT_EQ(hf("hfconvmesh", {x, vert, facesZero, w, 0.7}), kSentinel);
}

TEST(LibraryConvolution, LineRadius) {
    // R >= 1: kernel width 1; the threshold is the field of the last segment
    // at distance R beside its first end point, so that point is on the
    // surface.
    Vec b = {0, 0, 0}, e = {2, 0, 0};
    Vec x = {0, 1.5, 0};
    EXPECT_NEAR(hf("hfconvliner", {x, b, e, 1.5}), 0.0, 1e-14);
    x = {0, 0, 1.5};
    EXPECT_NEAR(hf("hfconvliner", {x, b, e, 1.5}), 0.0, 1e-14);
    // In general: field with width 1/R (R < 1) minus that threshold.
    const double r = 0.4, s = 1 / r;
    x = {0.7, 0.3, 0.2};
    const double at = segmentIntegral(x, &b[0], &e[0], s);
    Vec side = {0, r, 0};
    const double threshold = segmentIntegral(side, &b[0], &e[0], s);
    EXPECT_NEAR(hf("hfconvliner", {x, b, e, r}), at - threshold, 1e-8);
    // The running sum is clamped at 1: ten copies of a segment through x.
    Vec b10, e10;
    for (int i = 0; i < 10; ++i) {
        b10.insert(b10.end(), {0, 0, 0});
        e10.insert(e10.end(), {2, 0, 0});
    }
    const double rr = 0.1;
    Vec sideR = {0, rr, 0};
    const double thresholdR = segmentIntegral(sideR, &b[0], &e[0], 1 / rr);
    x = {1, 0, 0};
    EXPECT_NEAR(hf("hfconvliner", {x, b10, e10, rr}), 1.0 - thresholdR, 1e-8);
    // The count comes from the end-point array: an extra begin point is
    // ignored.
    Vec b2 = {0, 0, 0, 9, 9, 9};
    x = {0.7, 0.3, 0.2};
    EXPECT_DOUBLE_EQ(hf("hfconvliner", {x, b2, e, r}), hf("hfconvliner", {x, b, e, r}));
}

// ---------------------------------------------------------------------------
// Dispatch

// Well-formed arguments for every routine, by name: arrays of the sizes
// the routine needs, and scalars.
std::map<std::string, std::vector<Arg>> wellFormedArgs(std::deque<Vec>& store) {
    store.clear();  // a deque: references to its items stay valid as it grows
    auto a = [&](Vec v) -> Arg {
        store.push_back(std::move(v));
        return Arg(store.back());
    };
    auto pt = [&] { return a({0.3, -0.2, 0.4}); };
    std::map<std::string, std::vector<Arg>> m;
    m["hfsphere"] = {pt(), a({0, 0, 0}), 1.0};
    m["hfellipsoid"] = {pt(), a({0, 0, 0}), 1.0, 2.0, 3.0};
    for (const char* n : {"hftorusx", "hftorusy", "hftorusz"}) m[n] = {pt(), a({0, 0, 0}), 1.0, 0.3};
    for (const char* n : {"hfellcylx", "hfellcyly", "hfellcylz", "hfellconex", "hfellconey",
                          "hfellconez"})
        m[n] = {pt(), a({0, 0, 0}), 0.5, 0.7};
    for (const char* n : {"hfcylinderx", "hfcylindery", "hfcylinderz", "hfconex", "hfconey",
                          "hfconez"})
        m[n] = {pt(), a({0, 0, 0}), 0.5};
    m["hfblock"] = {pt(), a({-1, -1, -1}), 2.0, 2.0, 2.0};
    m["hfblobby"] = {pt(), a({0, 1}), a({0, 0}), a({0, 0}), a({1, 2}), a({1, 1}), 0.5};
    m["hfmetaball"] = {pt(), a({0, 1}), a({0, 0}), a({0, 0}), a({1, 2}), a({1, 1}), 0.5};
    m["hfsoft"] = {pt(), a({0, 1}), a({0, 0}), a({0, 0}), a({1, 2}), 0.5};
    m["hfscale3d"] = {pt(), 1.0, 2.0, 3.0};
    m["hfshift3d"] = {pt(), 1.0, 2.0, 3.0};
    for (const char* n : {"hfrotate3dx", "hfrotate3dy", "hfrotate3dz"}) m[n] = {pt(), 0.5};
    m["hfblenduni"] = {0.1, -0.2, 0.5, 1.0, 1.0};
    m["hfblendint"] = {0.1, -0.2, 0.5, 1.0, 1.0};
    for (const char* n : {"hftwistx", "hftwisty", "hftwistz"}) m[n] = {pt(), -1.0, 1.0, 0.0, 1.0};
    m["hfstretch3d"] = {pt(), a({0, 0, 0}), 1.0, 2.0, 3.0};
    for (const char* n : {"hftaperx", "hftapery", "hftaperz"}) m[n] = {pt(), -1.0, 1.0, 0.5, 1.5};
    m["hfconvpoint"] = {pt(), a({0, 0, 0, 1, 0, 0}), a({1, 2}), 0.3};
    m["hfconvline"] = {pt(), a({0, 0, 0, 1, 1, 1}), a({1, 0, 0, 2, 1, 1}), a({1, 2}), 0.3};
    m["hfconvarc"] = {pt(),          a({0, 0, 0, 1, 0, 0}), a({1, 0.5}), a({120, 270}),
                      a({0, 0, 1, 0, 1, 0}), a({0, 30}), a({2, 3}), 0.3};
    m["hfconvtriangle"] = {pt(), a({0, 0, 0, 1, 0, 0, 0, 1, 0}), a({2}), 0.3};
    m["hfconvliner"] = {pt(), a({0, 0, 0, 0, 1, 0}), a({1, 0, 0, 0, 1, 1}), 0.5};
    m["hfconvcurve"] = {pt(), a({0, 0, 0, 1, 0, 0, 1, 1, 0}), a({2, 3}), 0.3};
    m["hfconvmesh"] = {pt(), a({0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}), a({1, 2, 3, 1, 2, 4}),
                       a({2, 3}), 0.3};
    m["hfnoiseg"] = {pt(), 1.0, 2.0, 0.5};
    m["hfsuperell"] = {pt(), a({0, 0, 0}), 1.0, 1.0, 1.0, 0.5, 0.8};
    m["hfspacemapcubic"] = {pt(), a({0, 0, 0}), a({0.3, 0, 0}), a({1, 1, 1})};
    m["hfspacemapexp"] = {pt(), a({0, 0, 0}), a({0.3, 0, 0}), a({1, 1, 1})};
    return m;
}

TEST(LibraryDispatch, EveryIdRunsOnWellFormedArguments) {
    std::deque<Vec> store;
    const auto args = wellFormedArgs(store);
    const auto& table = lib::functions();
    ASSERT_EQ(table.size(), 46u);
    for (size_t id = 0; id < table.size(); ++id) {
        const auto& info = table[id];
        SCOPED_TRACE(info.name);
        ASSERT_EQ(lib::findFunction(info.name), static_cast<int>(id));
        auto it = args.find(info.name);
        ASSERT_NE(it, args.end()) << "no test arguments for " << info.name;
        ASSERT_EQ(it->second.size(), info.params.size());
        lib::Args<double> a;
        for (size_t i = 0; i < info.params.size(); ++i) {
            const Arg& arg = it->second[i];
            ASSERT_EQ(info.params[i] == lib::ParamKind::Array, arg.array != nullptr) << i;
            a.arrays.push_back(arg.array);
            a.scalars.push_back(arg.value);
        }
        double v = 0.0;
        EXPECT_NO_THROW(v = lib::call<double>(static_cast<int>(id), a));
        EXPECT_TRUE(std::isfinite(v)) << v;
        EXPECT_NE(v, kSentinel);
    }
    EXPECT_EQ(lib::findFunction("hfnosuch"), -1);
}

TEST(LibraryDispatch, IdsFollowTheTable) {
    // The dispatcher's ids must name the same routines as the table.
    using Id = lib::detail::Id;
    const std::vector<std::pair<Id, const char*>> pairs = {
        {Id::Sphere, "hfsphere"},          {Id::Ellipsoid, "hfellipsoid"},
        {Id::TorusZ, "hftorusz"},          {Id::TorusX, "hftorusx"},
        {Id::TorusY, "hftorusy"},          {Id::EllCylX, "hfellcylx"},
        {Id::EllCylY, "hfellcyly"},        {Id::EllCylZ, "hfellcylz"},
        {Id::CylinderX, "hfcylinderx"},    {Id::CylinderY, "hfcylindery"},
        {Id::CylinderZ, "hfcylinderz"},    {Id::Block, "hfblock"},
        {Id::Blobby, "hfblobby"},          {Id::Metaball, "hfmetaball"},
        {Id::Soft, "hfsoft"},              {Id::Scale3D, "hfscale3d"},
        {Id::Shift3D, "hfshift3d"},        {Id::Rotate3DZ, "hfrotate3dz"},
        {Id::Rotate3DY, "hfrotate3dy"},    {Id::Rotate3DX, "hfrotate3dx"},
        {Id::BlendUni, "hfblenduni"},      {Id::BlendInt, "hfblendint"},
        {Id::TwistZ, "hftwistz"},          {Id::TwistY, "hftwisty"},
        {Id::TwistX, "hftwistx"},          {Id::Stretch3D, "hfstretch3d"},
        {Id::TaperZ, "hftaperz"},          {Id::TaperY, "hftapery"},
        {Id::TaperX, "hftaperx"},          {Id::ConvPoint, "hfconvpoint"},
        {Id::ConvLine, "hfconvline"},      {Id::ConvArc, "hfconvarc"},
        {Id::ConvTriangle, "hfconvtriangle"}, {Id::ConvLineR, "hfconvliner"},
        {Id::ConvCurve, "hfconvcurve"},    {Id::ConvMesh, "hfconvmesh"},
        {Id::NoiseG, "hfnoiseg"},          {Id::Superell, "hfsuperell"},
        {Id::ConeX, "hfconex"},            {Id::ConeY, "hfconey"},
        {Id::ConeZ, "hfconez"},            {Id::EllConeX, "hfellconex"},
        {Id::EllConeY, "hfellconey"},      {Id::EllConeZ, "hfellconez"},
        {Id::SpaceMapCubic, "hfspacemapcubic"}, {Id::SpaceMapExp, "hfspacemapexp"},
    };
    ASSERT_EQ(pairs.size(), static_cast<size_t>(Id::Count));
    ASSERT_EQ(lib::functions().size(), static_cast<size_t>(Id::Count));
    for (const auto& [id, name] : pairs)
        EXPECT_EQ(lib::findFunction(name), static_cast<int>(id)) << name;
}

TEST(LibraryDispatch, BadIdsAndArguments) {
    lib::Args<double> a;
    EXPECT_THROW(lib::call<double>(-1, a), std::out_of_range);
    EXPECT_THROW(lib::call<double>(46, a), std::out_of_range);
    // A missing array argument is a caller bug, reported as an exception.
    a.arrays = {nullptr, nullptr, nullptr};
    a.scalars = {0, 0, 1};
    EXPECT_THROW(lib::call<double>(lib::findFunction("hfsphere"), a), std::invalid_argument);
}

// ---------------------------------------------------------------------------
// Replicas of the conformance programs that exercise the library, checked
// against the reference's tables (tests/data/hyperfun/conformance).

struct Row {
    double x, y, z, a1, expected;
};

// Rows of NAME.tsv (none when the file is absent, which fails the check).
std::vector<Row> readTable(const std::string& name) {
    std::ifstream in(std::string(HG_TEST_DATA_DIR) + "/hyperfun/conformance/" + name + ".tsv");
    std::vector<Row> rows;
    if (!in) return rows;
    std::string line;
    std::getline(in, line);  // header
    while (std::getline(in, line)) {
        if (line.empty()) continue;
        std::istringstream ls(line);
        std::string f[5];
        for (auto& s : f) std::getline(ls, s, '\t');
        if (f[4] == "error") continue;  // no library table has runtime errors
        rows.push_back({std::strtod(f[0].c_str(), nullptr), std::strtod(f[1].c_str(), nullptr),
                        std::strtod(f[2].c_str(), nullptr), std::strtod(f[3].c_str(), nullptr),
                        std::strtod(f[4].c_str(), nullptr)});
    }
    return rows;
}

using Program = std::function<double(Vec& x, double a1)>;

void checkTable(const std::string& name, const Program& program) {
    const auto rows = readTable(name);
    EXPECT_FALSE(rows.empty()) << name << ".tsv not found under " << HG_TEST_DATA_DIR;
    EXPECT_EQ(rows.size(), 200u) << name;
    int failures = 0;
    for (size_t i = 0; i < rows.size(); ++i) {
        const Row& r = rows[i];
        Vec x = {r.x, r.y, r.z};
        const double v = program(x, r.a1);
        const double tol = std::max(1e-9 * std::fabs(r.expected), 1e-9);
        if (!(std::fabs(v - r.expected) <= tol)) {
            if (++failures <= 5)
                ADD_FAILURE() << name << " row " << i + 1 << " (" << r.x << ", " << r.y << ", "
                              << r.z << ", a1 " << r.a1 << "): got " << v << ", expected "
                              << r.expected;
        }
    }
    EXPECT_EQ(failures, 0) << name << ": " << failures << " of " << rows.size() << " rows differ";
}

// A number as the reference's scanner computes it: integer digits by
// v * 10 + d, fraction digits by v + d / 10^k (not correctly rounded, e.g.
// 0.15 and 1.17 come out one ulp high). No exponent part.
double lexNumber(const char* s) {
    double v = 0.0;
    int i = 0;
    while (std::isdigit(static_cast<unsigned char>(s[i]))) v = v * 10.0 + (s[i++] - '0');
    if (s[i] == '.') {
        ++i;
        double t = 10.0;
        while (std::isdigit(static_cast<unsigned char>(s[i]))) {
            v = v + (s[i++] - '0') / t;
            t = t * 10.0;
        }
    }
    return v;
}

// `a = b` in a HyperFun condition.
bool eq(double a, double b) { return std::fabs(a - b) < 1e-6; }

TEST(LibraryConformance, Primitives) {
    checkTable("sphere_attr", [](Vec& x, double a1) {
        Vec centre = {0.5, -0.25, 1};
        return hf("hfsphere", {x, centre, a1});
    });
    checkTable("ellipsoid", [](Vec& x, double a1) {
        Vec c1 = {-1, 0, 0.5}, c2 = {0.75, 0.25, -0.5};
        const double e1 = hf("hfellipsoid", {x, c1, 2.0, 1.0, 0.5});
        const double e2 = hf("hfellipsoid", {x, c2, 0.6 * a1, 1.2, 0.8});
        return rUnion(e1, e2);
    });
    checkTable("block", [](Vec& x, double) {
        Vec corner = {-1, -0.75, -0.5}, hole = {-0.25, -0.25, -1};
        const double outer = hf("hfblock", {x, corner, 2.0, 1.5, 1.0});
        const double inner = hf("hfblock", {x, hole, 0.5, 0.5, 2.0});
        return rDiff(outer, inner);
    });
    checkTable("cylinders", [](Vec& x, double) {
        Vec o = {0, 0, 0};
        const double cx = hf("hfcylinderx", {x, o, 0.4});
        const double cy = hf("hfcylindery", {x, o, 0.5});
        const double cz = hf("hfcylinderz", {x, o, 0.6});
        const double bound = hf("hfsphere", {x, o, 1.5});
        return rInter(rUnion(rUnion(cx, cy), cz), bound);
    });
    checkTable("ellcyl", [](Vec& x, double) {
        Vec c = {0.2, -0.1, 0}, corner = {-1.2, -1.2, -1.2};
        const double ex = hf("hfellcylx", {x, c, 0.3, 0.6});
        const double ey = hf("hfellcyly", {x, c, 0.8, 0.4});
        const double ez = hf("hfellcylz", {x, c, 0.5, 0.9});
        return rInter(rUnion(rUnion(ex, ey), ez), hf("hfblock", {x, corner, 2.4, 2.4, 2.4}));
    });
    checkTable("tori", [](Vec& x, double) {
        Vec c = {0, 0, 0}, cx = {0.3, 0, 0};
        const double tz = hf("hftorusz", {x, c, 1.2, 0.3});
        const double tx = hf("hftorusx", {x, cx, 1.0, 0.25});
        const double ty = hf("hftorusy", {x, c, 0.8, 0.2});
        return rUnion(rUnion(tz, tx), ty);
    });
    checkTable("cones", [](Vec& x, double) {
        Vec apex = {0, 0, 0}, apx = {0, 1.5, 0}, apy = {1.5, 0, 0.5};
        const double kz = rInter(rInter(hf("hfconez", {x, apex, 0.6}), 1 - x[2]), 1 + x[2]);
        const double kx = rInter(rInter(hf("hfconex", {x, apx, 0.3}), 0.8 - x[0]), x[0] + 0.8);
        const double ky = rInter(rInter(hf("hfconey", {x, apy, 0.45}), 0.7 - x[1]), x[1] + 0.7);
        return rUnion(rUnion(kz, kx), ky);
    });
    checkTable("ellcones", [](Vec& x, double) {
        Vec c = {0.1, -0.2, 0.05}, o = {0, 0, 0};
        const double qx = hf("hfellconex", {x, c, 0.5, 0.25});
        const double qy = hf("hfellconey", {x, c, 0.3, 0.6});
        const double qz = hf("hfellconez", {x, c, 0.7, 0.35});
        return rInter(rUnion(rUnion(qx, qy), qz), hf("hfsphere", {x, o, 1.4}));
    });
    checkTable("superell", [](Vec& x, double a1) {
        Vec c = {0, 0.2, -0.1};
        return hf("hfsuperell", {x, c, 1.2, 0.8, 1.0, a1, 0.6});
    });
    checkTable("sentinel", [](Vec& x, double a1) {
        Vec c = {0, 0, 0}, flat = {0, 0};
        double r = hf("hfsphere", {x, c, 1.0});
        if (eq(a1, 1)) r = hf("hfellipsoid", {x, c, 1.0, 0.0, 1.0});
        if (eq(a1, 2)) r = hf("hfblock", {x, c, 1.0, -1.0, 1.0});
        if (eq(a1, 3)) {
            flat[0] = x[0];
            flat[1] = x[1];
            r = hf("hfsphere", {flat, c, 1.0});
        }
        if (eq(a1, 4)) r = hf("hfsuperell", {x, c, 1.0, 1.0, 1.0, 0.0, 1.0});
        if (eq(a1, 5)) r = hf("hfellcylz", {x, c, 0.0000001, 1.0});
        return r;
    });
}

TEST(LibraryConformance, Skeletal) {
    checkTable("blobby", [](Vec& x, double a1) {
        Vec px = {-0.6, 0.5, 0.1}, py = {0, 0.3, -0.5}, pz = {0.2, -0.1, 0.4};
        Vec fall = {3, 4.5, 6}, weight = {1, 0.8, 1.2};
        return hf("hfblobby", {x, px, py, pz, fall, weight, a1});
    });
    checkTable("metaball", [](Vec& x, double) {
        Vec cx = {0, 0.9, -0.7, 3}, cy = {0, 0.2, 0.4, 3}, cz = {0, -0.3, 0.1, 3};
        Vec weight = {1, 0.7, 0.9, 5}, reach = {1.1, 0.8, 0.9, -1};
        return hf("hfmetaball", {x, cx, cy, cz, weight, reach, 0.3});
    });
    checkTable("soft", [](Vec& x, double) {
        Vec sx = {-0.5, 0.5, 0}, sy = {0, 0, 0.6}, sz = {0, 0.1, -0.2}, reach = {0.9, 0.8, 0.7};
        return hf("hfsoft", {x, sx, sy, sz, reach, 0.25});
    });
}

TEST(LibraryConformance, Convolution) {
    checkTable("convpoint", [](Vec& x, double) {
        Vec pts = {0, 0, 0, 1, 0, 0, 0, 1.2, 0, -0.4, -0.3, 0.9};
        Vec width = {1.5, 2, 2.5, 1.8};
        return hf("hfconvpoint", {x, pts, width, 0.35});
    });
    checkTable("convline", [](Vec& x, double) {
        Vec b = {-1, 1, 0, 1, 1, 0, -1, -1, 0.2};
        Vec e = {1, 1, 0, -1, -1, 0.2, 1, -1, 0};
        Vec w = {3, 2.5, 3.5};
        return hf("hfconvline", {x, b, e, w, 0.6});
    });
    checkTable("convarc", [](Vec& x, double a1) {
        Vec cen = {0, 0, 0, 0.5, 0.5, 0.3, -0.4, 0.2, -0.3};
        Vec rad = {1, 0.6, 0.8};
        Vec span = {120, 270, 90};
        Vec axis = {0, 0, 1, 1, 0, 0, 0.3, 0.5, 0.8};
        Vec turn = {30, 0, 45};
        Vec w = {3, 4, 2.5};
        const double first = hf("hfconvarc", {x, cen, rad, span, axis, turn, w, 0.5});
        const double second = hf("hfconvarc", {x, cen, rad, span, axis, turn, w, 0.5});
        return first + 0.5 * (second - first) * a1;
    });
    checkTable("convtriangle", [](Vec& x, double) {
        Vec tri = {0, 0, 0, 1.2, 0, 0, 0.3, 1, 0, 0, 0, 0, 0.3, 1, 0, -0.2, 0.4, 0.9};
        Vec w = {2.5, 3};
        return hf("hfconvtriangle", {x, tri, w, 0.45});
    });
    checkTable("convcurve", [](Vec& x, double) {
        Vec path = {-1.5, 0, 0, -0.5, 0.6, 0.1, 0.4, -0.2, 0.3, 1.2, 0.5, -0.2, 1.6, 1.2, 0.4};
        Vec w = {3, 3.5, 2.8, 4};
        return hf("hfconvcurve", {x, path, w, 0.25});
    });
    checkTable("convmesh", [](Vec& x, double) {
        Vec vert = {0, 0, 0, 1, 0, 0, 0.5, 0.9, 0, 0.5, 0.3, 0.8};
        Vec faces = {1, 2, 3, 1, 2, 4, 2, 3, 4, 3, 1, 4};
        Vec w = {3, 3, 3.5, 2.5};
        return hf("hfconvmesh", {x, vert, faces, w, 0.7});
    });
    checkTable("convliner", [](Vec& x, double a1) {
        Vec b = {-1, 0, 0, 0, -1, 0.3}, e = {1, 0, 0, 0, 1, 0.3};
        return hf("hfconvliner", {x, b, e, a1});
    });
}

TEST(LibraryConformance, BlendsAndNoise) {
    checkTable("blends", [](Vec& x, double a1) {
        Vec c1 = {-0.5, 0, 0}, c2 = {0.5, 0, 0};
        const double f1 = hf("hfsphere", {x, c1, 0.7});
        const double f2 = hf("hfsphere", {x, c2, 0.6});
        if (a1 >= 0) return hf("hfblenduni", {f1, f2, a1, 1.0, 1.5});
        return hf("hfblendint", {f1, f2, -a1, 0.8, 1.2});
    });
    checkTable("noiseg", [](Vec& x, double a1) {
        Vec o = {0, 0, 0};
        const double noise = hf("hfnoiseg", {x, a1, 3.5, 1.4});
        const double ball = hf("hfsphere", {x, o, 1.0});
        return ball + noise;
    });
}

TEST(LibraryConformance, Transforms) {
    checkTable("transforms", [](Vec& x, double a1) {
        Vec box = {-0.5, -0.3, -0.2}, o = {0, 0, 0};
        Vec p = x;
        hf("hfshift3d", {p, 0.3, -0.2, 0.1});
        hf("hfrotate3dz", {p, 0.5});
        hf("hfrotate3dx", {p, -0.7});
        hf("hfrotate3dy", {p, a1});
        hf("hfscale3d", {p, 1.5, 0.8, 1.2});
        const double first = hf("hfblock", {p, box, 1.0, 0.6, 0.4});
        Vec q = x;
        hf("hfscale3d", {q, 0.5, 1.0, 2.0});
        hf("hfshift3d", {q, 0.0, 0.9, 0.0});
        const double second = hf("hfsphere", {q, o, 0.6});
        return rUnion(first, second);
    });
    checkTable("twists", [](Vec& x, double a1) {
        Vec corner = {-0.3, -0.3, -1};
        Vec p = x;
        hf("hftwistz", {p, -1.0, 1.0, 0.0, a1});
        const double bar = hf("hfblock", {p, corner, 0.6, 0.6, 2.0});
        p = x;
        hf("hftwistx", {p, -1.2, 1.2, -0.8, 0.8});
        hf("hftwisty", {p, 0.0, 1.5, 0.3, -0.4});
        // The reference's scanner reads 0.15 as 0.1 + 5/100, one ulp above
        // the nearest double; with that value the rows match bit for bit.
        corner = {-1.2, -0.2, -lexNumber("0.15")};
        const double plate = hf("hfblock", {p, corner, 2.4, 0.4, 0.3});
        return rUnion(bar, plate);
    });
    checkTable("tapers", [](Vec& x, double a1) {
        Vec o = {0, 0, 0};
        Vec p = x;
        hf("hftaperz", {p, -1.0, 1.0, 1.0, a1});
        const double tz =
            rInter(rInter(hf("hfcylinderz", {p, o, 0.5}), 1.2 - x[2]), x[2] + 1.2);
        p = x;
        hf("hftaperx", {p, -1.0, 1.0, 0.4, 1.3});
        const double tx =
            rInter(rInter(hf("hfcylinderx", {p, o, 0.3}), 1.2 - x[0]), x[0] + 1.2);
        p = x;
        hf("hftapery", {p, -0.5, 0.8, 1.5, 0.6});
        const double ty = rInter(rInter(hf("hfcylindery", {p, o, 0.35}), 1 - x[1]), x[1] + 1);
        return rUnion(rUnion(tz, tx), ty);
    });
    checkTable("stretch", [](Vec& x, double a1) {
        Vec anchor = {0.2, 0.1, -0.1}, c = {0.2, 0.1, -0.1};
        hf("hfstretch3d", {x, anchor, 1.8, a1, 0.6});
        return hf("hfsphere", {x, c, 0.5});
    });
    checkTable("spacemap", [](Vec& x, double) {
        Vec o = {0, 0, 0};
        Vec src = {0.8, 0, 0, 0, 0, -0.8}, dst = {1.3, 0.2, 0, 0, 0.1, -1.2};
        Vec ratio = {0.8, 0.8, 0.8, 0.6, 0.6, 0.6};
        Vec src2 = {0, 0.8, 0}, dst2 = {0.1, 1.1, 0.3}, ratio2 = {0.5, 0.7, 0.5};
        Vec p = x;
        hf("hfspacemapcubic", {p, src, dst, ratio});
        hf("hfspacemapexp", {p, src2, dst2, ratio2});
        return hf("hfsphere", {p, o, 0.8});
    });
    // Operands right to left: the in-place rewriting makes the order visible.
    checkTable("eval_order", [](Vec& x, double a1) {
        Vec c = {0, 0, 0};
        const double shift1 = hf("hfshift3d", {x, 0.5, 0.0, 0.0});
        const double p = hf("hfsphere", {x, c, 1.0}) * shift1;
        const double sphere2 = hf("hfsphere", {x, c, 1.0});
        const double q = hf("hfshift3d", {x, 0.0, 0.5, 0.0}) * sphere2;
        const double radius = 1 + 0 * hf("hfrotate3dz", {x, a1});
        const double r = hf("hfsphere", {x, c, radius});
        return p + 2 * q + 3 * r + x[0];
    });
}

}  // namespace
