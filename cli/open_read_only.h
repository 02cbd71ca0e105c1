// A session folder or a garden file opened for reading only, as `export`
// and `turntable` take it: the session's journal played (the folder is not
// changed, a session open elsewhere is read as its journal stands now) or
// the garden file as written. Problems are printed on stderr.
#pragma once

#include <memory>
#include <string>

#include "garden/app/garden_session.h"

namespace hg::garden::cli {

// Null with `status` set (2: bad input) when `input` cannot be opened; the
// warnings of a damaged or unplayable journal are printed, and `doing`
// ("exporting", "rendering") says what the command does with what it read.
std::unique_ptr<GardenSession> openReadOnly(const std::string& input, const SessionSettings& settings,
                                            const std::string& doing, int& status);

// Sculpture `name` of `session` with a grid to use, or -1 after printing
// why not, with `status` set: 2 when there is none (with the nearest name
// when it is a near miss, and the garden's names), 1 when it is missing.
int findUsableSculpture(const GardenSession& session, const std::string& input, const std::string& name, int& status);

// The extension of `path` in lower case (".json").
std::string lowerExtension(const std::string& path);

}  // namespace hg::garden::cli
