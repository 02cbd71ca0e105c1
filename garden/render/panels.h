// Dear ImGui panels of the desktop garden. They need only an ImGui context
// inside a frame (between ImGui::NewFrame and ImGui::Render), not GL, so
// they run headless in tests.
#pragma once

#include <functional>
#include <string>

#include <glm/vec2.hpp>

#include "garden/app/frame_stats.h"
#include "garden/app/memory_report.h"

namespace hg::garden {

class GardenSession;
class ChunkArena;
struct KeyRow;

// A window with the last frame's time per stage against the budget, the
// morph, remesh and upload counters and queues, triangles and draw calls,
// and a graph of the frame time over the history with the budget as a line.
// Folded to its title at first; `toggle` unfolds it, or folds it again (F3).
// `memory` (may be empty): what the session holds, shown below the counters;
// called only while the panel is unfolded (a report walks every grid).
// `gpuMeshes` (may be null): the renderer's chunk arena, whose buffers'
// size and use are shown beside it.
void drawStatsPanel(const FrameHistory& history, bool toggle = false,
                    const std::function<const MemoryReport&()>& memory = {}, const ChunkArena* gpuMeshes = nullptr);
constexpr const char* kStatsPanelTitle = "Frame stats (F3)";

// The tool panel: the tool in hand and its parameters (the session's
// ToolSettings, which the tools read), reverse, the selected sculpture's
// mirror plane, its edit count and a button that discards its edits, undo
// and redo. The desktop's key for each control is named beside it.
void drawToolPanel(GardenSession& session);

// While the session's work is not all on disk (garden/action/action_sink.h):
// a banner at `topLeft`, `width` wide, red for actions held in memory after
// a failed write (the folder, the reason, a Retry button), amber for a
// session opened read-only (the record it cannot play, what to do).
// Nothing when everything is saved. True when shown.
bool drawSaveBanner(GardenSession& session, glm::vec2 topLeft, float width);

// The key list, read from the key table (garden/render/key_table.h) (open:
// a window the user can close; closed: a hint line at `bottomCentre`, the
// middle of the window's bottom edge in pixels, to press F1).
void drawHelpPanel(bool& open, glm::vec2 bottomCentre);
// The key table's rows that `pick` takes (all without one) as a two-column
// table: the keys `keyWidth` pixels wide, what they do wrapped beside them.
void drawKeyRows(const char* id, float keyWidth, const std::function<bool(const KeyRow&)>& pick);

// The history panel (H): the undo history with each action's sculpture
// (the selection's highlighted, undone ones greyed), undo, redo and undo on
// the selected sculpture alone. `open` goes false when closed.
void drawHistoryPanel(GardenSession& session, bool& open);
// The history's actions, newest at the bottom (the panel's list, and the
// headset's history page).
void historyList(GardenSession& session);

// The first-run overlay: what the garden is, the few keys to start with
// (from the key table) and a button that dismisses it. `open` goes false
// when dismissed; true is returned in that frame (to remember it).
bool drawFirstRunPanel(bool& open);

// The "quit without saving?" question (a modal pop-up, opened by `ask`):
// what would be lost (`what`), Quit and Cancel (Esc). True when the user
// chose to quit.
bool drawQuitQuestion(bool ask, const std::string& what);

// The morph selector inside the current window: a triangle whose corners
// carry labels[0..2] (bottom left, bottom right, top); clicking or dragging
// in it moves `point`, kept inside the triangle, in the local frame of
// morph_triangle.h (weights by triangleWeights). True when `point` changed.
bool morphTriangleWidget(const char* const labels[3], glm::vec2& point, float side = 180.0f);

// The morph section of the Garden panel (nothing without a morph): the
// triangle widget and the weights line, both drawn from the session's
// weights each frame (a pick on the ground shows at once); a click or drag
// in the triangle sets them.
void drawMorphSection(GardenSession& session);
// The widget's point for the session's weights (morph_triangle.h's frame).
glm::vec2 morphSelectorPoint(const GardenSession& session);

}  // namespace hg::garden
