#include "garden/window/impostor_identity.h"

#include <cstring>
#include <string>

#include "garden/app/garden_session.h"
#include "garden/app/sculpture_sampling.h"
#include "garden/render/renderer.h"
#include "garden/sculpt/sculpture_edits.h"

namespace hg::garden {
namespace {

// FNV-1a over the bytes of each value, in order.
class Hash {
public:
    Hash& bytes(const void* data, std::size_t n) {
        const auto* p = static_cast<const unsigned char*>(data);
        for (std::size_t i = 0; i < n; ++i) {
            value_ ^= p[i];
            value_ *= 1099511628211ull;
        }
        return *this;
    }
    template <typename T>
    Hash& operator<<(const T& v) {
        return bytes(&v, sizeof v);
    }
    Hash& operator<<(const std::string& s) {
        *this << s.size();
        return bytes(s.data(), s.size());
    }
    std::uint64_t value() const { return value_; }

private:
    std::uint64_t value_ = 14695981039346656037ull;
};

Hash& operator<<(Hash& h, const RenderMaterial& m) {
    return h << m.baseColor.x << m.baseColor.y << m.baseColor.z << m.specular << m.shininess << m.kind << m.metallic
             << m.detailScale << m.edges << m.cavity;
}

}  // namespace

ImpostorId impostorId(const GardenSession& session, std::size_t sculpture, const RenderMaterial& material) {
    const Sculpture& st = session.sculptures()[sculpture];
    const bool unedited = !st.edits || st.edits->list().empty();
    const auto& specs = session.garden().sculptures;
    if (st.source.kind == SculptureSource::Kind::HyperFun && unedited && st.source.spec >= 0 &&
        static_cast<std::size_t>(st.source.spec) < specs.size()) {
        Hash h;
        h << std::string("hyperfun") << sampledSourceKey(specs[static_cast<std::size_t>(st.source.spec)])
          << st.sourceStamp << material;
        return {h.value(), 1};
    }
    Hash key;
    key << std::string("own") << sculpture;
    Hash version;
    version << st.frameGeneration << (st.queue ? st.queue->changes() : 0) << material;
    return {key.value(), version.value()};
}

}  // namespace hg::garden
