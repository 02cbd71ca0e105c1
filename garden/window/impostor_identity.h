// Which impostor a sculpture shows (garden/render/impostor_atlas.h;
// docs/rendering.md, "Impostors"). An unedited sculpture of a HyperFun file
// is what its garden entry says (file, body, a[], box, resolution, band,
// the file's time) in its material: every copy of it in the garden shares
// one impostor, so a thousand copies of nine sculptures need nine. Any
// other (edited, a morph's result, a scan or a mesh) has its own, whose
// version follows its surface (RemeshQueue::changes, a grid rebuilt in
// another frame) and its material.
#pragma once

#include <cstddef>
#include <cstdint>

#include "garden/render/impostor_atlas.h"

namespace hg::garden {

class GardenSession;
struct RenderMaterial;

struct ImpostorId {
    ImpostorKey key = 0;
    std::uint64_t version = 0;
};

ImpostorId impostorId(const GardenSession& session, std::size_t sculpture, const RenderMaterial& material);

}  // namespace hg::garden
