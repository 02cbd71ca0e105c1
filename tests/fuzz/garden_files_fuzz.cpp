// libFuzzer target for the garden's JSON readers (docs/design.md §10: every file
// reader is fuzzed): garden files and replay scripts. Any input must be
// accepted or refused with a JsonError that names a path and a reason;
// any other exception, a crash or undefined behaviour is a bug.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "garden/replay/replay_script.h"
#include "garden/scene/garden_file.h"
#include "garden/scene/json_reader.h"

using namespace hg::garden;

namespace {

void check(bool ok) {
    if (!ok) std::abort();
}

template <class Parse>
void refusedOrAccepted(Parse parse) {
    try {
        parse();
    } catch (const JsonError& e) {
        check(!e.path().empty() && !e.reason().empty());
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    refusedOrAccepted([&] {
        const Garden g = parseGarden(text, "fuzz.json", "/nowhere");
        for (const SculptureSpec& s : g.sculptures) check(s.resolution > 0 && !s.name.empty());
        for (const hg::garden::MorphSpec& m : g.morphs)
            for (std::size_t i : m.sourceIndex) check(i < g.sculptures.size());
    });
    refusedOrAccepted([&] {
        const ReplayScript s = parseReplayScript(text, "fuzz.json", "/nowhere");
        check(!s.steps.empty() && s.timestep > 0.0);
        for (const ReplayStep& step : s.steps) check(step.frames >= 1);
    });
    return 0;
}
