// Garden coordinates (double triples, as files and scripts give them) as
// the float vectors the session, navigator and renderer work in.
#pragma once

#include <array>

#include <glm/vec3.hpp>

namespace hg::garden {

inline glm::vec3 toGlm(const std::array<double, 3>& v) {
    return {static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])};
}
inline glm::vec3 toGlm(const double v[3]) {
    return {static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2])};
}

}  // namespace hg::garden
