// The tool intents' tools (garden/hands/tool_intents.h) and the session's
// (garden/sculpt/tool_settings.h), one for one. GardenSession applies the
// intents (applyToolIntents, garden/app/tool_intents.cpp).
#pragma once

#include "garden/hands/tool_intents.h"
#include "garden/sculpt/tool_settings.h"

namespace hg::garden {

ToolSettings::Kind toolKindOf(ToolChoice choice);
ToolChoice toolChoiceOf(ToolSettings::Kind kind);

}  // namespace hg::garden
