#include "xr/xr_result.h"

#include <openxr/openxr_reflection.h>

namespace hg::xr {

std::string XrFailure::resultName(XrResult r) {
#define HG_RESULT_NAME(name, value) \
    case name: return #name;
    switch (r) { XR_LIST_ENUM_XrResult(HG_RESULT_NAME) default: break; }
#undef HG_RESULT_NAME
    return "XrResult " + std::to_string(static_cast<int>(r));
}

}  // namespace hg::xr
