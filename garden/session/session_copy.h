// A copy of a session folder: the desktop's Duplicate (the copy is made and
// the user goes on in the original) and Save As (the user goes on in the
// copy). Every file but the writer's lock and temporaries is copied through
// the checked writes (io/checked_write.h) into TO.partial-PID, which is
// renamed to TO only when whole: a copy is whole or absent.
#pragma once

#include <string>

namespace hg::garden {

class SessionRecorder;

// Copies the session `recorder` writes into `to` (a folder that is missing
// or empty, not inside the session). Refused while finished actions wait
// in memory (the copy would lack them). "" or why not.
std::string copySession(const SessionRecorder& recorder, const std::string& to);

}  // namespace hg::garden
