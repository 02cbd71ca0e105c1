// The desktop's "Add a sculpture" section: a HyperFun file or a mesh becomes
// a new sculpture ahead of the viewer, sized to the garden and selected, one
// undoable action; a broken file is refused with the parser's message and
// nothing is added. Drawn through ImGui without a window.
#include <gtest/gtest.h>

#include <imgui.h>

#include "garden/app/garden_session.h"
#include "garden/desktop/add_panel.h"
#include "tests/garden/session_garden.h"
#include "tests/render/headless_imgui.h"

namespace hg::garden {
namespace {

class AddPanelTest : public test::SmallGardenSession {};

TEST_F(AddPanelTest, AFileIsAddedAheadOfTheViewerSizedAndSelected) {
    // A ball of radius 10 units: sized to 1.5 m, standing on the ground.
    const std::string file = write("big.hf", "my_model(x[3], a[1]) { my_model = 100 - (x[1]^2 + x[2]^2 + x[3]^2); }\n");
    const std::size_t before = session->sculptures().size();
    AddPanel panel;
    ASSERT_EQ(panel.add(*session, file), "");
    ASSERT_EQ(session->sculptures().size(), before + 1);
    const Sculpture& s = session->sculptures().back();
    EXPECT_EQ(s.name, "big");
    EXPECT_EQ(session->selected(), static_cast<int>(before));
    EXPECT_NE(panel.status().find("added 'big'"), std::string::npos);
    // 3 m ahead of the start (the eye at z 8, looking towards -z), centred,
    // on the ground, about 1.5 m across.
    EXPECT_NEAR(s.placement.position[2], 5.0, 0.2);
    EXPECT_NEAR(s.placement.position[0], 0.0, 0.2);
    const frep::Box3& box = s.volume->frame.modelBox;
    EXPECT_NEAR((box.hi[0] - box.lo[0]) * s.scale(), 1.5, 0.01);
    EXPECT_NEAR(s.placement.position[1] + box.lo[1] * s.scale(), 0.0, 1e-6);
    ASSERT_TRUE(session->undo());
    EXPECT_EQ(session->findSculpture("big"), -1);
}

TEST_F(AddPanelTest, AMeshIsAddedSizedAndItsBadLineIsShown) {
    // A tetrahedron 3 units across along x: sized to 1.5 m, on the ground.
    const std::string file = write("tet.obj", "v 0 0 0\nv 3 0 0\nv 0 2 0\nv 0 0 2\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
    AddPanel panel;
    ASSERT_EQ(panel.add(*session, file), "");
    const Sculpture& s = session->sculptures().back();
    EXPECT_EQ(s.name, "tet");
    EXPECT_TRUE(s.meshed());
    EXPECT_NEAR(3.0 * s.scale(), 1.5, 1e-6);
    EXPECT_NEAR(s.placement.position[1], 0.0, 1e-6);  // its lowest point (y 0) on the ground
    const std::string bad = write("bad.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n");
    EXPECT_NE(panel.add(*session, bad), "");
    EXPECT_NE(panel.status().find("bad.ply"), std::string::npos) << panel.status();
}

TEST_F(AddPanelTest, ABrokenFileIsRefusedWithItsMessageAndTheButtonDrawsIt) {
    const std::string file = write("broken.hf", "my_model(x[3], a[1]) {\n  my_model = 1 - ;\n}\n");
    const std::size_t before = session->sculptures().size();
    AddPanel panel;
    EXPECT_NE(panel.add(*session, file), "");
    EXPECT_NE(panel.status().find("broken.hf:2:"), std::string::npos) << panel.status();
    EXPECT_NE(panel.add(*session, ""), "");
    EXPECT_EQ(session->sculptures().size(), before);
    // The section draws in a window without an ImGui error.
    createHeadlessImGui(ImVec2(1280, 720));
    for (int frame = 0; frame < 2; ++frame) {  // a new window shows from its second frame
        ImGui::NewFrame();
        ImGui::Begin("Garden");
        ImGui::SetNextItemOpen(true);
        panel.draw(*session);
        ImGui::End();
        ImGui::Render();
    }
    EXPECT_GT(ImGui::GetDrawData()->TotalVtxCount, 0);
    ImGui::DestroyContext();
}

}  // namespace
}  // namespace hg::garden
