// libFuzzer target for the session journal's reader (docs/design.md §10): any bytes
// are a journal refused with a message, or records with at most a damaged
// tail that names its record and offset inside the input. Every record read
// writes back to a line the reader reads again to the same record.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "garden/session/journal.h"

using namespace hg::garden;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string text(reinterpret_cast<const char*>(data), size);
    const JournalRead r = parseJournal(text, "fuzz.hgj");
    if (!r.ok()) {
        if (!r.records.empty() || r.error.empty()) std::abort();
        return 0;
    }
    if (r.goodBytes > size) std::abort();
    if (r.damaged() && (r.damagedOffset != r.goodBytes || r.damagedRecord != r.records.size() + 1)) std::abort();
    for (const Action& rec : r.records) {
        const std::string json = actionJson(rec);
        if (actionJson(parseAction(json, "again")) != json) std::abort();
    }
    return 0;
}
