// Extraction (issue 22, docs/sketching.md "Selections"): the part of a
// sculpture inside a deformable model's selection becomes a new sculpture.
// Its source is the sculpture written as HyperFun (hyperfun_export.h) cut
// to the selection's balls, held whole in an AddAction, so it is
// journalled, undone and exported like any added sculpture, and the new
// sculpture's values are the source's inside the selection exactly.
#pragma once

#include <string>

namespace hg::garden {

class GardenSession;

// The part of sculpture `from` inside model `model`'s selection as a new
// sculpture named `name` ("": FROM-part); "" or why not.
std::string extractPart(GardenSession& session, const std::string& from, const std::string& model,
                        const std::string& name);

}  // namespace hg::garden
