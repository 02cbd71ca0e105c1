// One HyperFun file as a ready Model: parse, pick the body, bind a[]. The
// errors come back as text (every diagnostic with its file, line, column and
// caret) instead of being printed, so that the garden can show a broken
// sculpture as missing with its message and the command line can print the
// same text.
#pragma once

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "frep/language/ast.h"
#include "frep/eval/model.h"

namespace hg::garden {

struct ModelFile {
    std::shared_ptr<const frep::Program> program;  // set when the file parsed
    std::optional<frep::Model> model;              // set when everything worked
    std::string error;                             // "" when `model` is set; else why, ending in '\n'

    bool ok() const { return model.has_value(); }
};

// `body` "": `my_model`, else the first body (HyperFun's default).
ModelFile loadModelFile(const std::string& path, const std::string& body, const std::vector<double>& a);
// The same from the program's text; `label` names it in messages (a file as
// the user gave it, "sketch"): a sculpture added to a running session
// keeps its text in the journal, not a path (docs/session-format.md).
ModelFile modelFromText(const std::string& text, const std::string& label, const std::string& body,
                        const std::vector<double>& a);

// The body named `name` (case-insensitive), or the default body for "".
// Returns -1 and sets `why` ("FILE: error: no body named 'x'; the file
// defines: A B\n") when there is no such body.
int findBodyOrExplain(const frep::Program& program, const std::string& name, const std::string& file,
                      std::string& why);

}  // namespace hg::garden
