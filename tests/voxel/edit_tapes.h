// Edit tapes for the voxel tests of edit regions and leaf snapshots, built
// here without the garden's edit list (garden/sculpt/edit_list.h): balls
// added to or carved from the base value W, and a model's own tape times
// the volume's normalization (what the sampler stores, before the clamp),
// plus voxel-by-voxel comparisons of two grids.
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <cstring>
#include <vector>

#include "frep/compiler/tape.h"
#include "frep/compiler/tape_builder.h"
#include "voxel/volume.h"

namespace hg::voxel::test {

struct Ball {
    std::array<double, 3> centre;
    double radius;
    bool add = true;  // added (max with the ball), else carved (min with its complement)
};

// W with each ball added or carved in turn: a ball's field is
// scale * (r^2 - |p - c|^2), positive inside.
inline frep::Tape ballsTape(const std::vector<Ball>& balls, double scale) {
    frep::TapeBuilder b;
    using frep::Op;
    std::uint32_t f = b.w();
    const std::uint32_t xyz[3] = {b.x(), b.y(), b.z()};
    for (const Ball& ball : balls) {
        std::uint32_t d2 = frep::kNoReg;
        for (int a = 0; a < 3; ++a) {
            const std::uint32_t d = b.op(Op::Sub, xyz[a], b.constant(ball.centre[static_cast<std::size_t>(a)]));
            const std::uint32_t sq = b.op(Op::Mul, d, d);
            d2 = d2 == frep::kNoReg ? sq : b.op(Op::Add, d2, sq);
        }
        const std::uint32_t g =
            b.op(Op::Mul, b.op(Op::Sub, b.constant(ball.radius * ball.radius), d2), b.constant(scale));
        f = ball.add ? b.op(Op::Max, f, g) : b.op(Op::Min, f, b.op(Op::Neg, g));
    }
    return b.finish(f);
}

// `tape` (a compiled model: pure operations only) with its result times
// `scale`, rebuilt on a fresh builder: in float the product is the
// sampler's f * float(scale) (voxel/box_walker.cpp), bit for bit. A tape
// with a fallible or fused operation fails the test.
inline frep::Tape scaledTape(const frep::Tape& tape, double scale) {
    frep::TapeBuilder b;
    using frep::Op;
    std::vector<std::uint32_t> reg(tape.registers, frep::kNoReg);
    const auto in = [&](std::uint32_t r) { return r == frep::kNoReg ? frep::kNoReg : reg[r]; };
    for (std::size_t i = 0; i < tape.code.size(); ++i) {
        const frep::Instr& ins = tape.code[i];
        std::uint32_t v;
        switch (ins.op) {
            case Op::X: v = b.x(); break;
            case Op::Y: v = b.y(); break;
            case Op::Z: v = b.z(); break;
            case Op::Const: v = b.constant(ins.imm); break;
            case Op::W: v = b.w(); break;
            default:
                if (frep::opCanFail(ins.op) || frep::fusedParamCount(ins.op) > 0) {
                    ADD_FAILURE() << "scaledTape: " << frep::opName(ins.op) << " is not a pure operation";
                    return tape;
                }
                v = b.op(ins.op, in(ins.a), in(ins.b), in(ins.c));
        }
        reg[tape.out[i]] = v;
    }
    return b.finish(b.op(Op::Mul, reg[tape.result], b.constant(scale)));
}

// Voxels of `box` whose values (bit for bit) or active states differ
// between a and b; with `what`, the first few are reported as failures.
inline std::size_t differingVoxels(const Volume& a, const Volume& b, const IndexBox& box, const char* what = nullptr) {
    std::size_t n = 0;
    for (int k = box.lo[2]; k <= box.hi[2]; ++k)
        for (int j = box.lo[1]; j <= box.hi[1]; ++j)
            for (int i = box.lo[0]; i <= box.hi[0]; ++i) {
                const float va = a.value(i, j, k), vb = b.value(i, j, k);
                if (std::memcmp(&va, &vb, sizeof va) != 0 || a.active(i, j, k) != b.active(i, j, k)) {
                    if (n++ < 3 && what)
                        ADD_FAILURE() << what << " voxel (" << i << ", " << j << ", " << k << "): " << va
                                      << (a.active(i, j, k) ? " on" : " off") << " vs " << vb
                                      << (b.active(i, j, k) ? " on" : " off");
                }
            }
    return n;
}

// `box` grown by `margin` voxels on every side.
inline IndexBox grown(const IndexBox& box, int margin) {
    return IndexBox::fromCorners(box.lo[0] - margin, box.lo[1] - margin, box.lo[2] - margin, box.hi[0] + margin,
                                 box.hi[1] + margin, box.hi[2] + margin);
}

}  // namespace hg::voxel::test
