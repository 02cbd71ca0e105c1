// The desktop's panel layout (issue 23, docs/desktop.md "Sessions"): where
// the ImGui panels stand, their sizes and which are collapsed, as ImGui's
// own ini text. It goes with a session, in DIR/view.json's "panels"
// (garden/session/session_view.h), written when the view is; outside a
// session none is kept (io.IniFilename is off: no imgui.ini in the folder
// the program was started from), and every run starts with the defaults.
#pragma once

#include <string>

namespace hg::garden {

// The current ImGui context's layout ("" without a context).
std::string panelLayout();

// Puts `layout` on the current context: panels already drawn move at once,
// the others take it when first drawn. Nothing without a context.
void restorePanelLayout(const std::string& layout);

}  // namespace hg::garden
