// A sculpture of the running garden as one self-contained HyperFun file
// (docs/design.md §7, docs/export.md): its source bodies renamed so their names
// cannot clash (bodies they call come along, earlier in the file), the
// morph blend when it is the morph result, and `my_model`, the edited
// sculpture in its model frame, evaluating to the sculpture's field value
// for value in double precision:
//
//  * unedited: my_model is the source body itself (or a call of it with the
//    garden's a[]), so it evaluates exactly like its source file; the
//    morph result's my_model is the blend of its three sources;
//  * edited: the grid's field, clamp(normalization * f, -band, band) (the
//    morph: the blend), followed by every edit as the expression
//    edit_field.h builds, one statement per operation (hf_text.h), so the
//    file is linear in the edits and every value stays in [-band, band].
//
// The placement (move, turn, scale) is a comment: my_model is in the model
// frame. Mirrored strokes and perturbations are in the edit list already.
#pragma once

#include <cstddef>
#include <string>

namespace hg::garden {

struct SelectionMask;

class GardenSession;
struct Sculpture;

struct HyperFunExport {
    std::string text;             // the program ("" on error)
    std::string error;            // why there is none
    std::size_t edits = 0;        // edits written
    std::size_t pieces = 0;       // their pieces (segments, quadrics, impacts)
    std::size_t statements = 0;   // statements written in my_model (0: it is the source body itself)
    // Set when the file is likely too large for our own parser (about four
    // syntax nodes a statement against frep::ParseLimits::kMaxNodes); the
    // file is written all the same.
    std::string warning;
};

// The sculpture with index `sculpture` in session.sculptures(). A scanned
// volume's or a mesh's sculpture is refused (scanRefusal): HyperFun cannot
// read a volume or a mesh.
HyperFunExport exportHyperFun(const GardenSession& session, int sculpture);

// The part of sculpture `sculpture` inside `mask` (an extraction,
// garden/export/part_export.h): its field in voxels, then min with the
// mask's balls' field.
HyperFunExport exportHyperFunPart(const GardenSession& session, int sculpture, const SelectionMask& mask);

// Why a scanned volume's or a mesh's sculpture (Sculpture::gridOnly) has no
// HyperFun export, and what to use.
std::string scanRefusal(const GardenSession& session, const Sculpture& sculpture);

// A finished export's text written to `path` atomically (a failure leaves
// no file): "" on success, else why not.
std::string writeHyperFunExport(const HyperFunExport& exported, const std::string& path);

// exportHyperFun written to `path` atomically (a failure leaves no file):
// "" on success, else why not.
std::string exportSculptureHyperFun(const GardenSession& session, int sculpture, const std::string& path);

}  // namespace hg::garden
