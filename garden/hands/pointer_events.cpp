#include "garden/hands/pointer_events.h"

namespace hg::garden {

PointerFrame foldPointerEvents(const std::vector<PointerEvent>& events, PointerState& state) {
    PointerFrame f;
    bool toolPressed = false, lookPressed = false, gesturePressed = false;
    for (const PointerEvent& e : events) {
        switch (e.kind) {
            case PointerEvent::Kind::Move:
                if (state.lookDown) f.lookDelta += e.position - state.position;
                state.position = e.position;
                break;
            case PointerEvent::Kind::Press:
            case PointerEvent::Kind::Release: {
                const bool down = e.kind == PointerEvent::Kind::Press;
                state.position = e.position;
                if (e.button == PointerButton::Tool) {
                    if (down && !toolPressed) {
                        toolPressed = true;
                        f.toolPosition = e.position;
                    }
                    state.toolDown = down;
                } else if (e.button == PointerButton::Gesture) {
                    gesturePressed = gesturePressed || down;
                    state.gestureDown = down;
                } else {
                    lookPressed = lookPressed || down;
                    state.lookDown = down;
                }
                break;
            }
        }
    }
    f.toolPressed = toolPressed;
    f.toolButton = state.toolDown || toolPressed;
    f.lookButton = state.lookDown || lookPressed;
    f.gestureButton = state.gestureDown || gesturePressed;
    if (!toolPressed) f.toolPosition = state.position;
    return f;
}

}  // namespace hg::garden
