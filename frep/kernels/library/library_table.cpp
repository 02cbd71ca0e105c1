// Signatures of the library routines, in the order of the reference
// interpreter's registration table (argument kinds: A = array, R = scalar).
#include "frep/kernels/library/library.h"

namespace hg::frep::lib {
namespace {
constexpr ParamKind A = ParamKind::Array;
constexpr ParamKind R = ParamKind::Scalar;
}  // namespace

const std::vector<FunctionInfo>& functions() {
    static const std::vector<FunctionInfo> table = {
        {"hfsphere", "hfSphere", {A, A, R}},
        {"hfellipsoid", "hfEllipsoid", {A, A, R, R, R}},
        {"hftorusz", "hfTorusZ", {A, A, R, R}},
        {"hftorusx", "hfTorusX", {A, A, R, R}},
        {"hftorusy", "hfTorusY", {A, A, R, R}},
        {"hfellcylx", "hfEllCylX", {A, A, R, R}},
        {"hfellcyly", "hfEllCylY", {A, A, R, R}},
        {"hfellcylz", "hfEllCylZ", {A, A, R, R}},
        {"hfcylinderx", "hfCylinderX", {A, A, R}},
        {"hfcylindery", "hfCylinderY", {A, A, R}},
        {"hfcylinderz", "hfCylinderZ", {A, A, R}},
        {"hfblock", "hfBlock", {A, A, R, R, R}},
        {"hfblobby", "hfBlobby", {A, A, A, A, A, A, R}},
        {"hfmetaball", "hfMetaball", {A, A, A, A, A, A, R}},
        {"hfsoft", "hfSoft", {A, A, A, A, A, R}},
        {"hfscale3d", "hfScale3D", {A, R, R, R}},
        {"hfshift3d", "hfShift3D", {A, R, R, R}},
        {"hfrotate3dz", "hfRotate3DZ", {A, R}},
        {"hfrotate3dy", "hfRotate3DY", {A, R}},
        {"hfrotate3dx", "hfRotate3DX", {A, R}},
        {"hfblenduni", "hfBlendUni", {R, R, R, R, R}},
        {"hfblendint", "hfBlendInt", {R, R, R, R, R}},
        {"hftwistz", "hfTwistZ", {A, R, R, R, R}},
        {"hftwisty", "hfTwistY", {A, R, R, R, R}},
        {"hftwistx", "hfTwistX", {A, R, R, R, R}},
        {"hfstretch3d", "hfStretch3D", {A, A, R, R, R}},
        {"hftaperz", "hfTaperZ", {A, R, R, R, R}},
        {"hftapery", "hfTaperY", {A, R, R, R, R}},
        {"hftaperx", "hfTaperX", {A, R, R, R, R}},
        {"hfconvpoint", "hfConvPoint", {A, A, A, R}},
        {"hfconvline", "hfConvLine", {A, A, A, A, R}},
        {"hfconvarc", "hfConvArc", {A, A, A, A, A, A, A, R}},
        {"hfconvtriangle", "hfConvTriangle", {A, A, A, R}},
        {"hfconvliner", "hfConvLineR", {A, A, A, R}},
        {"hfconvcurve", "hfConvCurve", {A, A, A, R}},
        {"hfconvmesh", "hfConvMesh", {A, A, A, A, R}},
        {"hfnoiseg", "hfNoiseG", {A, R, R, R}},
        {"hfsuperell", "hfSuperell", {A, A, R, R, R, R, R}},
        {"hfconex", "hfConeX", {A, A, R}},
        {"hfconey", "hfConeY", {A, A, R}},
        {"hfconez", "hfConeZ", {A, A, R}},
        {"hfellconex", "hfEllConeX", {A, A, R, R}},
        {"hfellconey", "hfEllConeY", {A, A, R, R}},
        {"hfellconez", "hfEllConeZ", {A, A, R, R}},
        {"hfspacemapcubic", "hfSpaceMapCubic", {A, A, A, A}},
        {"hfspacemapexp", "hfSpaceMapExp", {A, A, A, A}},
    };
    return table;
}

int findFunction(std::string_view lowerName) {
    const auto& table = functions();
    for (size_t i = 0; i < table.size(); ++i)
        if (lowerName == table[i].name) return static_cast<int>(i);
    return -1;
}

}  // namespace hg::frep::lib
