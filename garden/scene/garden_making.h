// Gardens made or extended from the command line (docs/garden-format.md,
// "Bringing work in"): `hypergarden FILE.hf` opens a garden of that one
// sculpture, `hypergarden garden add GARDEN.json FILE` adds an entry to a
// garden file: a HyperFun file, a mesh ("mesh") or an OpenVDB volume
// ("volume": a level set's zero, or a fog volume's middle value). Both size the model to the garden (its box's longest side
// `size` metres, standing on the ground) and check the result by reading it
// back as a garden before anything is written.
#pragma once

#include <array>
#include <string>

#include "frep/kernels/box.h"

namespace hg::frep { class Model; }

namespace hg::garden {

// Where a model stands when it is sized to the garden: its box, the
// scale that makes the box's longest side `size` metres, and the position
// that centres it over (x, z) with its lowest point on the ground (y = 0).
struct SizedModel {
    frep::Box3 box;
    double scale = 1.0;
    std::array<double, 3> position{};
};
// "" on success, else why the model has no box.
std::string sizeModel(const frep::Model& model, double size, double x, double z, SizedModel& out);
// The same for a box already known (a mesh's bounds, a volume's solid).
void sizeBox(const frep::Box3& box, double size, double x, double z, SizedModel& out);

struct ModelToPlace {
    std::string file;         // as the user named it: .hf, a mesh (.stl, .obj, .ply) or a volume (.vdb)
    std::string name;         // "": the file's stem
    std::string body;         // "": my_model, else the first body
    int resolution = 128;     // voxels along the model box's longest side
    double size = 1.5;        // metres along the model box's longest side
};

// A volume's iso-value and side when the user names only its file: a level
// set's zero with the inside below it, otherwise (a fog volume, densities)
// the middle of its values with the inside above.
struct VolumeDefaults {
    double iso = 0.0;
    bool insideAbove = false;
};

// The model read from its file and sized as above, standing over (x, z):
// a HyperFun body's box, a mesh's bounds, a .vdb volume's solid (and its
// VolumeDefaults). false with `error` set (the reader's message, with the
// file and line) for a file that does not read, a .raw volume (its file
// does not say its layout) or a body given for a mesh or a volume. Also
// the session's add (garden/app/session_adding.cpp).
// Whether `file` is a mesh (.stl, .obj, .ply) or a volume (.vdb, .raw)
// rather than a HyperFun program, by its extension in any case.
bool isMeshOrVolumeFile(const std::string& file);

bool sizeModelFile(const ModelToPlace& m, double x, double z, SizedModel& out, VolumeDefaults& volume,
                   std::string& error);

// A whole garden file's text holding `model` alone, at the origin, with the
// visitor's start framing it; "" with `error` set when the file does not
// load (the parser's messages) or has no box.
std::string gardenOfOneModel(const ModelToPlace& model, std::string& error);

// `gardenText` (the file at `gardenPath`) with `model` added beside the
// sculptures already there (3 m past the furthest along +x), its file
// written relative to the garden's folder; keys keep their order. "" with
// `error` set for a broken model, a taken name or a garden that does not read.
std::string gardenWithModel(const std::string& gardenText, const std::string& gardenPath, const ModelToPlace& model,
                            std::string& error);

}  // namespace hg::garden
