// Reading a garden file (JSON, docs/garden-format.md). A bad file is refused
// as a whole with the JSON path of the first problem and what was expected;
// a sculpture whose HyperFun file is missing or broken does not stop the
// garden: it is marked missing with the parser's messages.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "frep/eval/model.h"
#include "garden/scene/garden.h"

namespace hg::voxel { class ScalarVolume; }
namespace hg::poly { struct Mesh; }

namespace hg::garden {

// One sculpture's source, ready to sample, or why not: its HyperFun body,
// the samples of a scanned volume (SculptureSpec::scan) or the triangles of
// a mesh (SculptureSpec::mesh).
struct SculptureLoad {
    std::shared_ptr<const frep::Program> program;
    std::optional<frep::Model> model;
    std::shared_ptr<const voxel::ScalarVolume> scan;
    std::shared_ptr<const poly::Mesh> mesh;
    std::string error;  // "" when `model`, `scan` or `mesh` is set; else the messages (file:line:col, caret), ending in '\n'

    bool ok() const { return model.has_value() || scan != nullptr || mesh != nullptr; }
};

struct GardenLoad {
    std::optional<Garden> garden;        // none: the file itself is refused
    std::string error;                   // "FILE: PATH: reason" when refused
    std::string errorPath;               // JSON path ("$.sculptures[2].box"), "line L, column C", or "" (unreadable)
    std::string errorReason;
    std::vector<SculptureLoad> sculptures;  // one per garden->sculptures, in order
    // Per morph (Garden::morphs): why it cannot run (a source is missing), "" when it can.
    std::vector<std::string> morphErrors;

    bool ok() const { return garden.has_value(); }
    std::size_t missingCount() const;
};

// Checks a garden document and returns it; relative sculpture files are
// resolved against `folder`. Throws JsonError (json_reader.h) at the first
// problem. Does not read the sculptures' files.
Garden parseGarden(const std::string& text, const std::string& file, const std::string& folder);

// Reads `path`, parses it, and loads every sculpture's HyperFun body (frep
// parser and compiler; no sampling).
GardenLoad loadGarden(const std::string& path);
// The same from the file's text (`path` names it in messages and resolves
// its relative sculpture files): a generated garden.
GardenLoad loadGardenText(const std::string& text, const std::string& path);

// The sculpture's model from its file, body and a[], its scanned volume
// read and its iso-value checked, or its mesh read (missing or broken files give an error
// naming the garden file's entry, not an exception). Used by loadGarden, and again when
// a file changed on disk.
SculptureLoad loadSculpture(const SculptureSpec& spec);
// The same from the program's text instead of spec.file (a sculpture added
// to a running session, garden/app/session_adding.cpp).
SculptureLoad sculptureFromText(const SculptureSpec& spec, const std::string& text);

}  // namespace hg::garden
