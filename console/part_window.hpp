// The PART page's window (console/part_window.cpp; issue 36): how the part
// is seen (the view, the camera, the painting) and the worker that makes
// its picture away from the event loop. Each frame the Session asks it for
// the page: when the part, the tool, the look or the room changed it copies
// the workshop (render::snapshot) and hands the copy to the worker, which
// paints the surfaces, renders the picture and turns it into cells
// (libchafa); the page shows the last picture made meanwhile. During a run
// a new picture is asked for only when the material changed.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <condition_variable>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <thread>

#include "console/term_image.hpp"
#include "core/render/part_view.hpp"
#include "core/sim/sim.hpp"
#include "pages/cells.hpp"
#include "pages/view.hpp"

namespace pupitre::console {

// What the terminal shows (app.cpp asks it; tests set it).
struct Screen {
    pages::Colours colours = pages::Colours::none;
    bool ascii = false;
    // The terminal draws pictures itself (sixel, kitty; term_image.hpp),
    // the cell's size in pixels.
    ImageProtocol protocol = ImageProtocol::none;
    int cell_w = 0, cell_h = 0;
    bool images() const { return protocol != ImageProtocol::none && cell_w > 0 && cell_h > 0; }
};

class PartWindow {
  public:
    PartWindow();
    ~PartWindow();
    PartWindow(const PartWindow&) = delete;
    PartWindow& operator=(const PartWindow&) = delete;

    // A PART key: "turn" (+/-), "tilt" (+/-), "zoom" (in/out), "pan"
    // (left/right/up/down), "view" (the next one), "fit", "paint". Returns
    // the news for the message line.
    std::string key(std::string_view what, std::string_view arg, bool mill);
    // :part view WORD; false when the machine has no such view.
    bool set_mode(render::PartMode m, bool mill);
    render::Look look(bool mill) const;
    render::Paint paint() const { return paint_; }

    // The page of this frame into v.part. `drawing`: what the part is held
    // against (null: none); `numbers`: the scale's numbers may be shown
    // (not in an exercise before :submit); `page` the page's rectangle.
    void fill(pages::View& v, const Sim& sim, const render::Drawing* drawing, bool numbers,
              pages::Rect page, const Screen& screen) const;
    // A picture is being made: the event loop comes back soon for it.
    bool busy() const;
    // Waits until the picture asked for is made (tests).
    void wait() const;
    // The last picture made, and its number (a new number: the terminal
    // draws it again); null when none.
    std::shared_ptr<const render::Picture> picture() const;
    uint64_t serial() const;
    // That picture as the terminal's own (Screen::protocol), null when the
    // terminal draws none.
    const std::string* sequence() const;

  private:
    struct Job;
    struct Made;
    void work();
    void post(std::unique_ptr<Job> job) const;
    void ask(Job& want, const workshop::Workshop& w, const Sim& sim,
             const render::Drawing* drawing) const;
    void show(pages::PartView& p, bool numbers) const;

    render::PartMode mode_lathe_ = render::PartMode::section, mode_mill_ = render::PartMode::iso;
    render::Camera cam_;
    render::Paint paint_ = render::Paint::deviation;

    // The worker and what passes between it and the loop.
    mutable std::mutex mu_;
    mutable std::condition_variable cv_;
    mutable std::unique_ptr<Job> next_;  // asked for, not yet taken
    mutable bool working_ = false;
    mutable std::shared_ptr<const Made> made_;  // the last one made
    bool stop_ = false;
    std::thread worker_;

    // The loop's side: what was asked for last, the scene it copied.
    struct Asked;
    mutable std::unique_ptr<Asked> asked_;
};

}  // namespace pupitre::console
