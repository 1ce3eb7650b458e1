// The PART page's window and its worker (see part_window.hpp).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "console/part_window.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "console/part_paper.hpp"
#include "core/i18n.hpp"
#include "pages/pages.hpp"

namespace pupitre::console {

// A picture asked of the worker.
struct PartWindow::Job {
    std::shared_ptr<const render::PartScene> scene;
    render::Look look;
    render::Paint paint = render::Paint::depth;
    int w = 0, h = 0, cols = 0, rows = 0;
    pages::Colours colours = pages::Colours::none;
    bool ascii = false, cells = true;
    ImageProtocol protocol = ImageProtocol::none;
    uint64_t number = 0;
};

// A picture made.
struct PartWindow::Made {
    std::shared_ptr<const render::PartScene> scene;
    std::shared_ptr<const render::Picture> picture;
    pages::CellImage cells;
    std::string sequence;  // the terminal's own picture
    uint64_t number = 0;
};

// What the loop asked for last, to tell when to ask again; and what the
// page shows now (kept here: the worker may make the next meanwhile).
struct PartWindow::Asked {
    const workshop::Workshop* shop = nullptr;
    uint64_t generation = ~uint64_t(0);
    Axes tool{};
    std::string drawing;
    bool numbers = true;
    render::Look look;
    render::Paint paint = render::Paint::depth;
    int w = 0, h = 0, cols = 0, rows = 0;
    pages::Colours colours = pages::Colours::none;
    bool ascii = false, cells = true;
    std::shared_ptr<const render::PartScene> scene;
    uint64_t number = 0;
    std::shared_ptr<const Made> shown;
};

PartWindow::PartWindow() : asked_(std::make_unique<Asked>()) {}

PartWindow::~PartWindow() {
    {
        std::lock_guard lk(mu_);
        stop_ = true;
    }
    cv_.notify_all();
    if (worker_.joinable()) worker_.join();
}

render::Look PartWindow::look(bool mill) const {
    render::Look l;
    l.mode = mill ? mode_mill_ : mode_lathe_;
    l.cam = cam_;
    return l;
}

bool PartWindow::set_mode(render::PartMode m, bool mill) {
    if (!render::mode_fits(m, mill)) return false;
    (mill ? mode_mill_ : mode_lathe_) = m;
    return true;
}

std::string PartWindow::key(std::string_view what, std::string_view arg, bool mill) {
    const double sign = arg == "-" || arg == "left" || arg == "down" || arg == "out" ? -1 : 1;
    const bool three_d = mill && mode_mill_ == render::PartMode::iso;
    if (what == "turn" || what == "tilt") {
        if (!three_d) return tr("the 3-D view turns and tilts (v: the next view)");
        cam_ = what == "turn" ? render::turned(cam_, 15 * sign) : render::tilted(cam_, 10 * sign);
        return strf(tr("turned %.0f°, tilted %.0f°"), cam_.yaw, cam_.pitch);
    }
    if (what == "zoom") cam_ = render::zoomed(cam_, sign > 0 ? 1.5 : 1 / 1.5);
    if (what == "pan") {
        const bool across = arg == "left" || arg == "right";
        // The part moves the other way: "pan left" shows more on the left.
        cam_ = render::panned(cam_, across ? -0.2 * sign : 0, across ? 0 : -0.2 * sign);
    }
    if (what == "fit") {
        cam_ = render::Camera{};
        return tr("the whole part");
    }
    if (what == "view") {
        render::PartMode& m = mill ? mode_mill_ : mode_lathe_;
        m = render::next_mode(m, mill);
        return strf(tr("view %s"), std::string(render::mode_word(m)).c_str());
    }
    if (what == "paint") {
        paint_ =
            paint_ == render::Paint::deviation ? render::Paint::depth : render::Paint::deviation;
        return paint_ == render::Paint::deviation ? tr("painted by the deviation from the drawing")
                                                  : tr("painted by the depth of cut");
    }
    return {};
}

// ---- the worker ----

void PartWindow::post(std::unique_ptr<Job> job) const {
    auto* self = const_cast<PartWindow*>(this);
    {
        std::lock_guard lk(mu_);
        next_ = std::move(job);
        if (!worker_.joinable()) self->worker_ = std::thread([self] { self->work(); });
    }
    cv_.notify_all();
}

void PartWindow::work() {
    std::shared_ptr<const render::PartScene> prepared_for;
    render::Paint prepared_paint = render::Paint::depth;
    std::shared_ptr<const render::Surfaces> sf;
    std::unique_lock lk(mu_);
    for (;;) {
        cv_.wait(lk, [&] { return stop_ || next_ != nullptr; });
        if (stop_) return;
        std::unique_ptr<Job> job = std::move(next_);
        working_ = true;
        lk.unlock();
        if (job->scene != prepared_for || job->paint != prepared_paint) {
            sf = render::prepare(*job->scene, job->paint);
            prepared_for = job->scene, prepared_paint = job->paint;
        }
        auto made = std::make_shared<Made>();
        made->scene = job->scene;
        made->number = job->number;
        made->picture = std::make_shared<const render::Picture>(
            render::render(*job->scene, *sf, job->look, job->w, job->h));
        if (job->cells)
            made->cells = pages::to_cells(made->picture->image, job->cols, job->rows, job->colours,
                                          job->ascii);
        else
            made->sequence =
                image_sequence(made->picture->image, job->protocol, job->cols, job->rows, 1);
        lk.lock();
        made_ = std::move(made);
        working_ = false;
        cv_.notify_all();
    }
}

bool PartWindow::busy() const {
    std::lock_guard lk(mu_);
    return next_ || working_ || (made_ && made_ != asked_->shown);
}

void PartWindow::wait() const {
    std::unique_lock lk(mu_);
    cv_.wait(lk, [&] { return !next_ && !working_; });
}

std::shared_ptr<const render::Picture> PartWindow::picture() const {
    return asked_->shown ? asked_->shown->picture : nullptr;
}

uint64_t PartWindow::serial() const {
    return asked_->shown ? asked_->shown->number : 0;
}

const std::string* PartWindow::sequence() const {
    if (!asked_->shown || asked_->shown->sequence.empty()) return nullptr;
    return &asked_->shown->sequence;
}

// ---- the page ----

namespace {

// The picture's pixels for a rectangle of cells: four by eight a cell (a
// cell is twice as tall as wide), or the terminal's own cell size when it
// draws the picture; at most 1.6 million.
void picture_size(const pages::Rect& a, const Screen& s, int& w, int& h) {
    w = a.w * (s.images() ? s.cell_w : 4);
    h = a.h * (s.images() ? s.cell_h : 8);
    const double most = 1.6e6, n = double(w) * double(h);
    if (n > most) {
        const double k = std::sqrt(most / n);
        w = std::max(8, int(w * k)), h = std::max(8, int(h * k));
    }
}

std::string title_of(const render::Look& l, const render::Surfaces* sf, bool mill,
                     const std::string& drawing) {
    std::string t = std::string(render::mode_word(l.mode));
    if (mill && l.mode == render::PartMode::iso)
        t += strf(tr(" turned %.0f° tilted %.0f°"), l.cam.yaw, l.cam.pitch);
    if (l.cam.zoom != 1) t += strf(tr(" x%.2g"), l.cam.zoom);
    (void)sf;
    return t + "  " +
           (drawing.empty() ? std::string(tr("painted by depth of cut"))
                            : strf(tr("deviation from %s"), drawing.c_str()));
}

}  // namespace

void PartWindow::fill(pages::View& v, const Sim& sim, const render::Drawing* drawing, bool numbers,
                      pages::Rect page, const Screen& screen) const {
    pages::PartView& p = v.part;
    p.colours = screen.colours;
    p.image = screen.images();
    p.numbers = numbers;
    const workshop::Workshop* w = sim.shop();
    p.workshop = w != nullptr;
    if (!w) return;
    const bool mill = w->is_mill();
    p.keys = mill ? tr("Left/Right turn, Up/Down tilt, +/- zoom, Shift+arrows pan, v view, f fit, "
                       "c paint; :part export FILE")
                  : tr("+/- zoom, Shift+arrows pan, f fit, c paint; :part export FILE");
    // The lines under the picture: a line for each dimension, one for the
    // lathe's stick-out (its number after :submit only).
    p.info = pages::part_info((drawing ? drawing->dims.size() : 0) + (!mill && numbers ? 1 : 0));
    Job want;
    const pages::Rect area = pages::part_area(page, p.info);
    want.look = look(mill);
    want.paint = drawing ? paint_ : render::Paint::depth;
    want.cols = area.w, want.rows = area.h;
    want.colours = screen.colours, want.ascii = screen.ascii, want.cells = !screen.images();
    want.protocol = screen.images() ? screen.protocol : ImageProtocol::none;
    picture_size(area, screen, want.w, want.h);
    ask(want, *w, sim, drawing);
    p.title = title_of(want.look, nullptr, mill, drawing ? drawing->name : std::string());
    show(p, numbers);
}

// Asks the worker for `want` when the part, the tool (not while a program
// runs), the drawing or the look changed since the last picture asked
// for, and the worker is idle (else a later frame asks).
void PartWindow::ask(Job& want, const workshop::Workshop& w, const Sim& sim,
                     const render::Drawing* drawing) const {
    Asked& a = *asked_;
    const std::string name = drawing ? drawing->name : std::string();
    const bool material = &w != a.shop || w.generation() != a.generation || name != a.drawing;
    const bool moved = sim.state() != RunState::running && sim.om() != a.tool;
    const bool looks = want.look != a.look || want.paint != a.paint || want.w != a.w ||
                       want.h != a.h || want.cols != a.cols || want.rows != a.rows ||
                       want.colours != a.colours || want.ascii != a.ascii || want.cells != a.cells;
    bool idle;
    {
        std::lock_guard lk(mu_);
        idle = !next_ && !working_;
    }
    if (!(material || moved || looks || !a.scene) || !idle) return;
    if (material || moved || !a.scene) {
        a.scene = render::snapshot(w, sim.om(), drawing);
        a.shop = &w, a.generation = w.generation(), a.tool = sim.om(), a.drawing = name;
    }
    a.look = want.look, a.paint = want.paint, a.w = want.w, a.h = want.h;
    a.cols = want.cols, a.rows = want.rows, a.colours = want.colours, a.ascii = want.ascii;
    a.cells = want.cells;
    want.scene = a.scene;
    want.number = ++a.number;
    post(std::make_unique<Job>(want));
}

// The last picture made, onto the page: its cells, its scale, its lines.
void PartWindow::show(pages::PartView& p, bool numbers) const {
    Asked& a = *asked_;
    {
        std::lock_guard lk(mu_);
        a.shown = made_;
    }
    if (!a.shown) {
        p.note = tr("drawing the part…");
        return;
    }
    if (!p.image) p.cells = &a.shown->cells;
    p.legend = a.shown->picture->legend;
    for (const render::DimReading& r : a.shown->scene->dims)
        p.lines.push_back({render::reading_colour(r, p.legend.span_um), dim_text(r)});
    if (numbers && a.shown->picture->has_stickout)
        p.lines.push_back(
            {pages::kNoColour, strf(tr("stick-out %.2f mm, from the jaws' face to the part's face"),
                                    a.shown->picture->stickout)});
}

}  // namespace pupitre::console
