// Where a running session's finished actions go, and whether they are
// safe (docs/session-format.md): the session folder's recorder is one; the
// desktop overlay and the headset panel show its status as a banner, and
// the command line reports it on stderr and in its exit status.
#pragma once

#include <cstddef>
#include <string>

#include "garden/action/action.h"

namespace hg::garden {

struct SaveStatus {
    enum class State {
        Saved,     // every finished action is on disk
        NotSaved,  // a write failed: the actions since are kept in memory, retried
        ReadOnly,  // the journal holds a record that cannot be played: nothing is written
    };
    State state = State::Saved;
    std::string folder;
    std::string reason;        // why not saved, or why read-only
    std::size_t unsaved = 0;   // finished actions held in memory only
    std::string remedy;        // what the user can do ("hypergarden session DIR --cut-at 25")
    // Counts state changes, so a view redraws its banner only when it changed.
    std::size_t revision = 0;

    bool saved() const { return state == State::Saved; }
    // One line for the banner and the terminal ("" when saved).
    std::string headline() const {
        const std::string held = std::to_string(unsaved) + (unsaved == 1 ? " action is" : " actions are");
        switch (state) {
            case State::Saved: return "";
            case State::NotSaved:
                return "NOT SAVED to " + folder + ": " + reason + " (" + held + " kept in memory and retried)";
            case State::ReadOnly:
                return "READ-ONLY: " + reason + (unsaved ? " (" + held + " not saved)" : std::string());
        }
        return "";
    }
};

// How far a journal played (GardenSession::restoreRecords).
struct JournalPlayed {
    std::size_t played = 0;  // records played (all of them, or those before the failed one)
    std::string action;      // the failed record's kind ("redo")
    std::string reason;      // why it cannot be played ("nothing to redo"); "" : all played
    bool ok() const { return reason.empty(); }
    // "record 25 (redo): nothing to redo", or "".
    std::string message() const {
        return ok() ? "" : "record " + std::to_string(played + 1) + " (" + action + "): " + reason;
    }
};

class JournalSink {
public:
    virtual ~JournalSink() = default;
    // A finished action (never called while a journal is being played).
    virtual void append(const Action& record) = 0;
    virtual SaveStatus saveStatus() const = 0;
    // Writes what is held in memory now (the banner's Retry); true when
    // everything is saved afterwards.
    virtual bool retrySave() = 0;
};

}  // namespace hg::garden
