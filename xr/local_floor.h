// XR_EXT_local_floor: LOCAL's origin dropped to the floor, gravity-aligned,
// facing where the user faced when the session began. Debian's OpenXR
// 1.0.20 headers predate the extension, so its name and enum (extension
// number 427: 1000000000 + 426 * 1000) are declared here; OpenXR 1.1 made
// the same value core as XR_REFERENCE_SPACE_TYPE_LOCAL_FLOOR.
#pragma once

#include <openxr/openxr.h>

namespace hg::xr {

inline constexpr const char* kLocalFloorExtensionName = "XR_EXT_local_floor";
inline constexpr XrReferenceSpaceType kReferenceSpaceLocalFloor = static_cast<XrReferenceSpaceType>(1000426000);

}  // namespace hg::xr
