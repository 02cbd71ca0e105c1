// The mock OpenXR runtime (xr/mock_runtime) through the real loader: the
// manifest in the build tree selected with XR_RUNTIME_JSON, an instance
// with the extensions the program enables, and a session on a hidden
// GLFW window's GL context. Without DISPLAY the GL tests skip, unless
// HG_REQUIRE_GL=1 (CI) makes that a failure.
#pragma once

#include <gtest/gtest.h>

#include <dlfcn.h>

#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <memory>
#include <string>

#include "../render/gl_fixture.h"
#include "garden/render/gl_context.h"

#include "xr/mock_runtime/mock_control.h"
#include "xr/xr_platform.h"

namespace hg::xr::test {

// Selects the mock runtime and clears what an earlier test set for it.
inline void useMockRuntime() {
    ::setenv("XR_RUNTIME_JSON", HG_MOCK_XR_MANIFEST, 1);
    for (const char* v : {"HG_MOCK_XR_SCRIPT", "HG_MOCK_XR_EVENTS", "HG_MOCK_XR_CONTROL", "HG_MOCK_XR_READBACK",
                          "HG_MOCK_XR_NO_STAGE", "HG_MOCK_XR_HEAD_YAW", "HG_MOCK_XR_APP_PERIODS",
                          "HG_MOCK_XR_VIEW_SIZE", "HG_MOCK_XR_NO_REFRESH_RATE",
                          "HG_MOCK_XR_NO_DEPTH24", "HG_MOCK_XR_BLEND_MODE", "HG_MOCK_XR_NO_LOCAL_FLOOR", "XR_ENABLE_API_LAYERS"})
        ::unsetenv(v);
    ::setenv("HG_MOCK_XR_NO_THROTTLE", "1", 1);
    // The user's own headset settings are not the tests' (a fresh file each test).
    const std::filesystem::path settings =
        std::filesystem::temp_directory_path() / ("hg_xr_test_settings_" + std::to_string(::getpid()) + ".json");
    std::filesystem::remove(settings);
    ::setenv("HG_XR_SETTINGS", settings.c_str(), 1);
}

// A function of the mock library the loader opened.
template <typename F>
F mockFunction(const char* name) {
    void* lib = ::dlopen(HG_MOCK_XR_LIBRARY, RTLD_NOW | RTLD_NOLOAD);
    if (!lib) return nullptr;
    F f = reinterpret_cast<F>(::dlsym(lib, name));
    ::dlclose(lib);
    return f;
}

class MockXr : public ::testing::Test {
protected:
    void SetUp() override {
        HG_REQUIRE_DISPLAY();
        useMockRuntime();
        XrInstanceCreateInfo info{XR_TYPE_INSTANCE_CREATE_INFO};
        std::strcpy(info.applicationInfo.applicationName, "hg_xr_tests");
        info.applicationInfo.apiVersion = XR_MAKE_VERSION(1, 0, 0);
        const char* extensions[] = {XR_KHR_OPENGL_ENABLE_EXTENSION_NAME, XR_KHR_COMPOSITION_LAYER_DEPTH_EXTENSION_NAME};
        info.enabledExtensionCount = 2;
        info.enabledExtensionNames = extensions;
        ASSERT_EQ(xrCreateInstance(&info, &instance), XR_SUCCESS);
        XrSystemGetInfo system{XR_TYPE_SYSTEM_GET_INFO};
        system.formFactor = XR_FORM_FACTOR_HEAD_MOUNTED_DISPLAY;
        ASSERT_EQ(xrGetSystem(instance, &system, &systemId), XR_SUCCESS);
    }
    void TearDown() override {
        if (session != XR_NULL_HANDLE) xrDestroySession(session);
        if (instance != XR_NULL_HANDLE) xrDestroyInstance(instance);
    }

    static garden::GlWindow& window() {
        static std::unique_ptr<garden::GlWindow> w = [] {
            garden::WindowOptions o;
            o.width = 64;
            o.height = 64;
            o.visible = false;
            return std::make_unique<garden::GlWindow>(o);
        }();
        w->makeCurrent();
        return *w;
    }

    XrResult askGraphicsRequirements() {
        PFN_xrVoidFunction f = nullptr;
        xrGetInstanceProcAddr(instance, "xrGetOpenGLGraphicsRequirementsKHR", &f);
        XrGraphicsRequirementsOpenGLKHR r{XR_TYPE_GRAPHICS_REQUIREMENTS_OPENGL_KHR};
        return reinterpret_cast<PFN_xrGetOpenGLGraphicsRequirementsKHR>(f)(instance, systemId, &r);
    }

    XrResult createSession() {
        GLFWwindow* w = window().handle();  // GLFW (and its X connection) first
        XrGraphicsBindingOpenGLXlibKHR binding{XR_TYPE_GRAPHICS_BINDING_OPENGL_XLIB_KHR};
        binding.xDisplay = glfwGetX11Display();
        binding.glxContext = glfwGetGLXContext(w);
        binding.glxDrawable = glfwGetGLXWindow(w);
        XrSessionCreateInfo info{XR_TYPE_SESSION_CREATE_INFO};
        info.next = &binding;
        info.systemId = systemId;
        return xrCreateSession(instance, &info, &session);
    }

    void makeSession() {
        ASSERT_EQ(askGraphicsRequirements(), XR_SUCCESS);
        ASSERT_EQ(createSession(), XR_SUCCESS);
    }

    // Polls events until the session is in `state` (false if they run out first).
    bool pollUntil(XrSessionState state) {
        for (int i = 0; i < 32; ++i) {
            XrEventDataBuffer e{XR_TYPE_EVENT_DATA_BUFFER};
            if (xrPollEvent(instance, &e) != XR_SUCCESS) return false;
            if (e.type == XR_TYPE_EVENT_DATA_SESSION_STATE_CHANGED) {
                seen.push_back(reinterpret_cast<XrEventDataSessionStateChanged*>(&e)->state);
                if (seen.back() == state) return true;
            }
        }
        return false;
    }

    void beginSession() {
        ASSERT_TRUE(pollUntil(XR_SESSION_STATE_READY));
        XrSessionBeginInfo begin{XR_TYPE_SESSION_BEGIN_INFO};
        begin.primaryViewConfigurationType = XR_VIEW_CONFIGURATION_TYPE_PRIMARY_STEREO;
        ASSERT_EQ(xrBeginSession(session, &begin), XR_SUCCESS);
    }

    XrSwapchain makeSwapchain(int64_t format) {
        XrSwapchainCreateInfo info{XR_TYPE_SWAPCHAIN_CREATE_INFO};
        info.format = format;
        info.width = 64;
        info.height = 64;
        info.sampleCount = info.faceCount = info.arraySize = info.mipCount = 1;
        XrSwapchain s = XR_NULL_HANDLE;
        EXPECT_EQ(xrCreateSwapchain(session, &info, &s), XR_SUCCESS);
        return s;
    }

    XrSpace stageSpace() {
        XrReferenceSpaceCreateInfo info{XR_TYPE_REFERENCE_SPACE_CREATE_INFO};
        info.referenceSpaceType = XR_REFERENCE_SPACE_TYPE_STAGE;
        info.poseInReferenceSpace.orientation.w = 1.0f;
        XrSpace s = XR_NULL_HANDLE;
        EXPECT_EQ(xrCreateReferenceSpace(session, &info, &s), XR_SUCCESS);
        return s;
    }

    XrFrameState waitAndBegin() {
        XrFrameState state{XR_TYPE_FRAME_STATE};
        EXPECT_EQ(xrWaitFrame(session, nullptr, &state), XR_SUCCESS);
        EXPECT_EQ(xrBeginFrame(session, nullptr), XR_SUCCESS);
        return state;
    }

    XrResult endFrame(XrTime time, const XrCompositionLayerBaseHeader* layer = nullptr) {
        XrFrameEndInfo end{XR_TYPE_FRAME_END_INFO};
        end.displayTime = time;
        end.environmentBlendMode = XR_ENVIRONMENT_BLEND_MODE_OPAQUE;
        end.layerCount = layer ? 1 : 0;
        end.layers = layer ? &layer : nullptr;
        return xrEndFrame(session, &end);
    }

    XrPath path(const char* p) {
        XrPath out = XR_NULL_PATH;
        EXPECT_EQ(xrStringToPath(instance, p, &out), XR_SUCCESS) << p;
        return out;
    }

    XrInstance instance = XR_NULL_HANDLE;
    XrSystemId systemId = XR_NULL_SYSTEM_ID;
    XrSession session = XR_NULL_HANDLE;
    std::vector<XrSessionState> seen;
};

}  // namespace hg::xr::test
