// Definition of lib::call: dispatches a routine id (its index in
// functions(), library_table.cpp) to the routine template. Included by
// library.cpp (V = double) and by the compiler (V = Sym).
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "frep/kernels/library/blends.h"
#include "frep/kernels/library/convolution.h"
#include "frep/kernels/library/library.h"
#include "frep/kernels/library/noise.h"
#include "frep/kernels/library/primitives.h"
#include "frep/kernels/library/skeletal.h"
#include "frep/kernels/library/transforms.h"
#include "frep/kernels/library/value_ops.h"

namespace hg::frep::lib {

namespace detail {

// Routine ids, in the order of the table in library_table.cpp (the tests
// check that each name maps to the id of the same name there).
enum class Id : int {
    Sphere, Ellipsoid, TorusZ, TorusX, TorusY, EllCylX, EllCylY, EllCylZ,
    CylinderX, CylinderY, CylinderZ, Block, Blobby, Metaball, Soft,
    Scale3D, Shift3D, Rotate3DZ, Rotate3DY, Rotate3DX, BlendUni, BlendInt,
    TwistZ, TwistY, TwistX, Stretch3D, TaperZ, TaperY, TaperX,
    ConvPoint, ConvLine, ConvArc, ConvTriangle, ConvLineR, ConvCurve, ConvMesh,
    NoiseG, Superell, ConeX, ConeY, ConeZ, EllConeX, EllConeY, EllConeZ,
    SpaceMapCubic, SpaceMapExp,
    Count
};

}  // namespace detail

template <class V>
V call(int id, const Args<V>& args) {
    using detail::Id;
    if (id < 0 || id >= static_cast<int>(Id::Count))
        throw std::out_of_range("hf library: no routine with id " + std::to_string(id));
    // Argument accessors by position; the parser has checked the kinds, so a
    // failure here is a bug in the caller.
    auto arr = [&](size_t i) -> std::vector<V>& {
        if (i >= args.arrays.size() || args.arrays[i] == nullptr)
            throw std::invalid_argument("hf library: argument " + std::to_string(i + 1) +
                                        " of routine " + std::to_string(id) +
                                        " must be an array");
        return *args.arrays[i];
    };
    auto val = [&](size_t i) -> const V& {
        if (i >= args.scalars.size())
            throw std::invalid_argument("hf library: argument " + std::to_string(i + 1) +
                                        " of routine " + std::to_string(id) + " is missing");
        return args.scalars[i];
    };

    switch (static_cast<Id>(id)) {
    // Primitives.
    case Id::Sphere: return hfSphere<V>(arr(0), arr(1), val(2));
    case Id::Ellipsoid: return hfEllipsoid<V>(arr(0), arr(1), val(2), val(3), val(4));
    case Id::TorusZ: return hfTorusZ<V>(arr(0), arr(1), val(2), val(3));
    case Id::TorusX: return hfTorusX<V>(arr(0), arr(1), val(2), val(3));
    case Id::TorusY: return hfTorusY<V>(arr(0), arr(1), val(2), val(3));
    case Id::EllCylX: return hfEllCylX<V>(arr(0), arr(1), val(2), val(3));
    case Id::EllCylY: return hfEllCylY<V>(arr(0), arr(1), val(2), val(3));
    case Id::EllCylZ: return hfEllCylZ<V>(arr(0), arr(1), val(2), val(3));
    case Id::CylinderX: return hfCylinderX<V>(arr(0), arr(1), val(2));
    case Id::CylinderY: return hfCylinderY<V>(arr(0), arr(1), val(2));
    case Id::CylinderZ: return hfCylinderZ<V>(arr(0), arr(1), val(2));
    case Id::Block: return hfBlock<V>(arr(0), arr(1), val(2), val(3), val(4));
    case Id::Superell:
        return hfSuperell<V>(arr(0), arr(1), val(2), val(3), val(4), val(5), val(6));
    case Id::ConeX: return hfConeX<V>(arr(0), arr(1), val(2));
    case Id::ConeY: return hfConeY<V>(arr(0), arr(1), val(2));
    case Id::ConeZ: return hfConeZ<V>(arr(0), arr(1), val(2));
    case Id::EllConeX: return hfEllConeX<V>(arr(0), arr(1), val(2), val(3));
    case Id::EllConeY: return hfEllConeY<V>(arr(0), arr(1), val(2), val(3));
    case Id::EllConeZ: return hfEllConeZ<V>(arr(0), arr(1), val(2), val(3));

    // Skeletal primitives.
    case Id::Blobby:
        return hfBlobby<V>(arr(0), arr(1), arr(2), arr(3), arr(4), arr(5), val(6));
    case Id::Metaball:
        return hfMetaball<V>(arr(0), arr(1), arr(2), arr(3), arr(4), arr(5), val(6));
    case Id::Soft: return hfSoft<V>(arr(0), arr(1), arr(2), arr(3), arr(4), val(5));

    // Transformations (rewrite the point array, return 1).
    case Id::Scale3D: return hfScale3D<V>(arr(0), val(1), val(2), val(3));
    case Id::Shift3D: return hfShift3D<V>(arr(0), val(1), val(2), val(3));
    case Id::Rotate3DZ: return hfRotate3DZ<V>(arr(0), val(1));
    case Id::Rotate3DY: return hfRotate3DY<V>(arr(0), val(1));
    case Id::Rotate3DX: return hfRotate3DX<V>(arr(0), val(1));
    case Id::TwistZ: return hfTwistZ<V>(arr(0), val(1), val(2), val(3), val(4));
    case Id::TwistY: return hfTwistY<V>(arr(0), val(1), val(2), val(3), val(4));
    case Id::TwistX: return hfTwistX<V>(arr(0), val(1), val(2), val(3), val(4));
    case Id::Stretch3D: return hfStretch3D<V>(arr(0), arr(1), val(2), val(3), val(4));
    case Id::TaperZ: return hfTaperZ<V>(arr(0), val(1), val(2), val(3), val(4));
    case Id::TaperY: return hfTaperY<V>(arr(0), val(1), val(2), val(3), val(4));
    case Id::TaperX: return hfTaperX<V>(arr(0), val(1), val(2), val(3), val(4));
    case Id::SpaceMapCubic: return hfSpaceMapCubic<V>(arr(0), arr(1), arr(2), arr(3));
    case Id::SpaceMapExp: return hfSpaceMapExp<V>(arr(0), arr(1), arr(2), arr(3));

    // Blends.
    case Id::BlendUni: return hfBlendUni<V>(val(0), val(1), val(2), val(3), val(4));
    case Id::BlendInt: return hfBlendInt<V>(val(0), val(1), val(2), val(3), val(4));

    // Convolution surfaces.
    case Id::ConvPoint: return hfConvPoint<V>(arr(0), arr(1), arr(2), val(3));
    case Id::ConvLine: return hfConvLine<V>(arr(0), arr(1), arr(2), arr(3), val(4));
    case Id::ConvArc:
        return hfConvArc<V>(arr(0), arr(1), arr(2), arr(3), arr(4), arr(5), arr(6), val(7));
    case Id::ConvTriangle: return hfConvTriangle<V>(arr(0), arr(1), arr(2), val(3));
    case Id::ConvLineR: return hfConvLineR<V>(arr(0), arr(1), arr(2), val(3));
    case Id::ConvCurve: return hfConvCurve<V>(arr(0), arr(1), arr(2), val(3));
    case Id::ConvMesh: return hfConvMesh<V>(arr(0), arr(1), arr(2), arr(3), val(4));

    // Noise.
    case Id::NoiseG: return hfNoiseG<V>(arr(0), val(1), val(2), val(3));

    case Id::Count: break;
    }
    throw std::out_of_range("hf library: no routine with id " + std::to_string(id));
}

}  // namespace hg::frep::lib
