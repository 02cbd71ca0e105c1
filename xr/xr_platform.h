// OpenXR's Xlib + OpenGL platform structures (XrGraphicsBindingOpenGLXlibKHR)
// and GLFW's native X11/GLX handles of a window, for the code that binds a
// session to the GLFW window's context (xr/headset.cpp, the XR tests).
// X11's None and Status macros are undone: they clash with our names.
#pragma once

#include <epoxy/gl.h>
#include <epoxy/glx.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#define XR_USE_PLATFORM_XLIB
#define XR_USE_GRAPHICS_API_OPENGL
#include <openxr/openxr.h>
#include <openxr/openxr_platform.h>
#undef None
#undef Status

// GLFW's native access (glfw3native.h would pull in the Xrandr headers,
// which the build does not otherwise need); Debian's GLFW is built for X11
// with GLX, so these are in libglfw.
extern "C" {
Display* glfwGetX11Display(void);
GLXContext glfwGetGLXContext(GLFWwindow* window);
GLXWindow glfwGetGLXWindow(GLFWwindow* window);
}
