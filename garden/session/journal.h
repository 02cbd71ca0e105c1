// The session's journal (docs/design.md §10, docs/session-format.md): one record per
// finished action, appended and synced to disk when the action ends, so a
// process killed at any moment loses no finished action. Records are in the
// sculpture's model frame, so replaying them rebuilds the same edits (and
// the same grids) bit for bit.
//
// The file is text: a header line "hypergarden-journal 1", then one line per
// record, "CRC32 JSON", where CRC32 (8 hex digits) covers the JSON text. A
// torn or damaged line ends what can be trusted: the reader keeps every
// record before it and reports where the damage starts.
#pragma once

#include <array>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "garden/action/action.h"

namespace hg::garden {

constexpr int kJournalVersion = 1;

struct JournalRead {
    std::vector<Action> records;
    // Refused outright (unreadable, not a journal, unknown version): nothing
    // is in `records`.
    std::string error;
    // A damaged tail: what is wrong, the 1-based number of the first bad
    // record and its byte offset; every record before it is in `records`.
    std::string damage;
    std::size_t damagedRecord = 0;
    std::uint64_t damagedOffset = 0;
    std::uint64_t goodBytes = 0;  // where the trusted part ends
    // Where each record's line starts (records[i] at recordOffsets[i]).
    std::vector<std::uint64_t> recordOffsets;

    bool ok() const { return error.empty(); }
    bool damaged() const { return !damage.empty(); }
};

JournalRead readJournal(const std::string& path);
JournalRead parseJournal(const std::string& text, const std::string& name);

// Appends records, each written whole and synced to disk before append()
// returns "" (io/checked_write.h). A failed append leaves the file as it
// was before it: what it wrote of the record is cut before the next try,
// so a record is on disk whole or not at all, and in order.
class JournalWriter {
public:
    JournalWriter() = default;
    ~JournalWriter();
    JournalWriter(const JournalWriter&) = delete;
    JournalWriter& operator=(const JournalWriter&) = delete;

    // Opens `path` for appending; the header is written with the first
    // record of a new (or empty) file. `truncateTo`: cut a damaged tail
    // first (the reader's goodBytes). "" on success, else why not.
    std::string open(const std::string& path, std::uint64_t truncateTo = ~std::uint64_t{0});
    std::string append(const Action& r);
    bool isOpen() const { return fd_ >= 0; }
    std::size_t written() const { return written_; }

private:
    int fd_ = -1;
    std::string path_;
    std::uint64_t goodSize_ = 0;  // the file's length after the last whole record
    bool torn_ = false;           // an append failed: cut back to goodSize_ first
    std::size_t written_ = 0;
};

std::uint32_t crc32(const std::string& text);

}  // namespace hg::garden
