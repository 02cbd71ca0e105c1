// The desktop's Export panel (docs/design.md §7): the selected sculpture written
// into the folder named in the panel (by default exports/ next to the
// session, or in the working folder without one) in the format picked.
// HyperFun is written at once; meshes are made on a worker thread from the
// exported FRep while the garden goes on, with a progress bar and a Cancel
// button.
#pragma once

#include <atomic>
#include <future>
#include <memory>
#include <string>

namespace hg::garden {

class GardenSession;

class ExportPanel {
public:
    // `folder`: where exports go by default (an `exports/` folder is made in it).
    explicit ExportPanel(std::string folder);
    ~ExportPanel();  // waits for an export under way
    ExportPanel(const ExportPanel&) = delete;
    ExportPanel& operator=(const ExportPanel&) = delete;

    // ImGui calls for one frame; the session is read only when the button is pressed.
    void draw(const GardenSession& session);
    // Starts exporting sculpture `index` as `extension` (".hf", ".stl", ...)
    // at `resolution` (0: the grid's); false (and status() says why) when it
    // cannot start. The path is FOLDER/FILE.EXT, FOLDER exportFolder() (made
    // when missing), FILE the name given (fileName, letters, digits, - and _
    // kept) or else the sculpture's name and the time.
    bool start(const GardenSession& session, int index, const std::string& extension, int resolution);
    // The file name the next export takes ("": NAME-TIME).
    void setFileName(const std::string& name) { fileName_ = name; }
    // The folder the next export goes into ("": the default, exports/ in
    // the constructor's folder), as typed in the panel's folder field.
    void setFolder(const std::string& folder);
    std::string exportFolder() const;
    bool busy() const;
    // Stops the export under way at its next check (io/progress.h: inside a
    // tile's sampling, between tiles, before the write): nothing is written,
    // and status() says it was cancelled. A file already being written is
    // let finish.
    void cancel();
    // The last export's outcome ("" before any); collects a finished worker.
    const std::string& status();
    const std::string& lastPath() const { return lastPath_; }

private:
    struct Work;
    std::string folder_;
    std::string status_;
    std::string lastPath_;
    int format_ = 0;
    int resolution_ = 0;
    std::string fileName_;
    char nameField_[128] = {};
    char folderField_[512] = {};
    int shownFor_ = -1;  // the selection the status line was about
    std::unique_ptr<Work> work_;
};

}  // namespace hg::garden
