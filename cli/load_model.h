// Loads a HyperFun file for a command: parse, report every error with its
// location, pick the body, build the Model.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "frep/eval/bounds.h"
#include "frep/eval/model.h"
#include "cli/commands.h"

namespace hg::garden::cli {

struct LoadedModel {
    std::shared_ptr<const frep::Program> program;
    std::string source;
    std::optional<frep::Model> model;
};

// Prints diagnostics to stderr and returns nullopt when the file cannot be
// used.
std::optional<LoadedModel> loadModel(const ModelOptions& options);

// The body named `name` (case-insensitive), or the default body for "".
// Returns -1 and prints the available bodies when there is no such body.
int pickBody(const frep::Program& program, const std::string& name, const std::string& file);

// The --box option: none when it was not given; false (after printing why)
// when it is not six numbers.
bool boxOption(const std::vector<double>& numbers, std::optional<frep::Box3>& box);

// Whether the output file can be written (checked before any work); prints
// why not. In output_writable.cpp: it needs the voxel library, which the
// kernel-only executable does not link (full_executable.h).
bool outputWritable(const std::string& path);

}  // namespace hg::garden::cli
