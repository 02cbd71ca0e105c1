// OpenXR results as errors: every call the program makes goes through
// check(), which throws XrFailure naming the call and the result
// ("xrCreateSession: XR_ERROR_GRAPHICS_DEVICE_INVALID").
#pragma once

#include <openxr/openxr.h>

#include <stdexcept>
#include <string>

namespace hg::xr {

class XrFailure : public std::runtime_error {
public:
    XrFailure(const std::string& call, XrResult result)
        : std::runtime_error(call + ": " + resultName(result)), result_(result) {}
    XrResult result() const { return result_; }
    // "XR_ERROR_HANDLE_INVALID", without an instance (the reflection table).
    static std::string resultName(XrResult r);

private:
    XrResult result_;
};

// Throws XrFailure for a failure; returns success codes (XR_SESSION_LOSS_PENDING,
// XR_FRAME_DISCARDED, ...) for the caller to look at.
inline XrResult check(XrResult r, const char* call) {
    if (XR_FAILED(r)) throw XrFailure(call, r);
    return r;
}

}  // namespace hg::xr
