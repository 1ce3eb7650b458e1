// pupitre plot (see cli_plot.hpp): the same loading and dry run as `run`, with
// a Toolpath as the sink, then one scene drawn by the SVG writer and by Cairo.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "console/cli_plot.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <vector>

#include "console/cli.hpp"
#include "console/plot_loader.hpp"
#include "console/workshop_io.hpp"
#include "core/i18n.hpp"
#include "core/interp/interp.hpp"
#include "core/output/cairo_plot.hpp"
#include "core/output/scene.hpp"
#include "core/output/svg.hpp"
#include "core/output/toolpath.hpp"
#include "core/plan/plan_sink.hpp"
#include "core/workshop/report.hpp"

namespace pupitre::cli {

namespace {

// Runs to the end as `run` does (stops are resumed), following the program's
// line types (E31000, E31001) and the first plane other than G17 it selects.
void run_collecting(Interpreter& in, Toolpath& path, int& plane_seen,
                    const workshop::Workshop* shop) {
    int rapid = -1, feed = -1;
    while (!shop || !shop->crashed()) {
        StepResult r = in.step();
        const auto& e = in.e_written();
        if (!e.empty()) {
            auto ir = e.find(31000), iff = e.find(31001);
            int nr = ir == e.end() ? -1 : int(ir->second),
                nf = iff == e.end() ? -1 : int(iff->second);
            if (nr != rapid || nf != feed) path.set_line_types(rapid = nr, feed = nf);
        }
        if (!plane_seen && in.modal().plane != 17) plane_seen = in.modal().plane;
        if (r != StepResult::running && r != StepResult::stopped) return;
    }
}

// The part where the program frame puts it: a point of the part is where the
// tool the program last used with a corrector reads it (Workshop::part_frame).
std::vector<std::vector<std::array<double, 2>>> part_in_program_frame(const workshop::Workshop& w,
                                                                      const Interpreter& in) {
    const Axes& om = in.machine_pos();
    const Axes& op = in.program_pos();
    const workshop::Workshop::Frame f = w.part_frame(om, op, in.modal().d);
    const double dz = f.dz, dx = f.dx;
    std::vector<std::vector<std::array<double, 2>>> out;
    if (const workshop::MillWorld* block = w.mill()) {
        // Seen from above where the program frame puts it, as the lathe's part.
        const workshop::P3 tip = w.tip3(om, false);
        out = workshop::block_from_above(*block);
        for (auto& poly : out)
            for (auto& p : poly) p[0] += op[X] - tip[0], p[1] += op[Y] - tip[1];
        return out;
    }
    for (const workshop::CPath& q : w.world().material()) {
        out.emplace_back();
        for (const auto& v : q) {
            workshop::Pt p = workshop::to_mm(v);
            out.back().push_back({p[0] + dz, p[1] + dx});
        }
    }
    return out;
}

// The workshop's crashes (printed, drawn as the block in error) and its part.
void draw_workshop(const workshop::Workshop& shop, const Interpreter& in, const ProgramMemory& mem,
                   const std::string& file, Toolpath& path) {
    for (const workshop::Crash& c : shop.crashes()) {
        Diag d = workshop::crash_diag(c);
        d.file = file;
        for (const auto& p : mem.programs())
            if (p->number == d.program) d.file = p->file;
        print_diag(d);
        path.add_error(d);
    }
    path.set_part(part_in_program_frame(shop, in));
}

PathPlane chosen_plane(const Toolpath& path, const MachineProfile& m, int plane_seen) {
    if (m.lathe || path.arc_plane() != 17 || !plane_seen) return path.default_plane();
    return plane_seen == 18 ? PathPlane::xz : plane_seen == 19 ? PathPlane::yz : PathPlane::xy;
}

// The pictures `plot` writes, in order: one scene, three back-ends.
struct Output {
    std::string PlotArgs::*file;
    const char* what;
    bool (*write)(const Scene&, const PlotArgs&, std::FILE*);
};
constexpr Output kOutputs[] = {
    {&PlotArgs::svg, "SVG",
     [](const Scene& s, const PlotArgs&, std::FILE* f) { return write_svg(s, f); }},
    {&PlotArgs::png, "PNG",
     [](const Scene& s, const PlotArgs& a, std::FILE* f) { return write_png(s, a.png_width, f); }},
    {&PlotArgs::pdf, "PDF",
     [](const Scene& s, const PlotArgs&, std::FILE* f) { return write_pdf(s, f); }},
};

int write_out(const Output& o, const Scene& scene, const PlotArgs& a) {
    const std::string& name = a.*o.file;
    bool to_stdout = name == "-" && o.file == &PlotArgs::svg;
    std::FILE* f = to_stdout ? stdout : std::fopen(name.c_str(), "wb");
    if (!f) {
        std::fprintf(stderr, tr("pupitre: %s: cannot create: %s\n"), name.c_str(),
                     std::strerror(errno));
        return kCantCreate;
    }
    errno = 0;
    bool ok = o.write(scene, a, f);
    int err = errno;
    if (f != stdout && std::fclose(f) != 0) ok = false;
    if (!ok && f != stdout) std::remove(name.c_str());  // no half-written picture
    if (!ok) {
        if (const std::string why = plot_module_error(); !why.empty() && o.file != &PlotArgs::svg)
            std::fprintf(stderr, tr("pupitre: %s: cannot write the %s: %s\n"), name.c_str(), o.what,
                         why.c_str());
        else if (err)
            std::fprintf(stderr, tr("pupitre: %s: cannot write the %s: %s\n"), name.c_str(), o.what,
                         std::strerror(err));
        else
            std::fprintf(stderr, tr("pupitre: %s: cannot write the %s\n"), name.c_str(), o.what);
        return kIoErr;
    }
    return kOk;
}

// --plane and the outputs; false after printing the problem.
bool plot_usage(const PlotArgs& a, PathPlane& plane) {
    if (!a.plane.empty() && !parse_plane(a.plane, plane)) {
        std::fprintf(stderr, tr("pupitre: --plane %s: expected xy, xz, yz or zx\n"),
                     a.plane.c_str());
        return false;
    }
    if ((a.svg.empty() && a.png.empty() && a.pdf.empty()) || a.files.empty()) {
        std::fputs(tr("pupitre: plot needs --svg, --png or --pdf OUT and a program file\n"),
                   stderr);
        return false;
    }
    return true;
}

// The program plot runs: the first one of the first file; null after
// printing the problem.
const ProgramText* main_program(const ProgramMemory& mem, const std::string& file) {
    for (const auto& p : mem.programs())
        if (p->file == file) return p.get();
    std::fprintf(stderr, tr("pupitre: %s: no program to run\n"), file.c_str());
    return nullptr;
}

// The drawing starts where the program starts, named after it, with the
// program's EM+ and EM- extremes when it gives them.
void start_drawing(Toolpath& path, const Interpreter& in, const ProgramText& main,
                   const MachineProfile& m) {
    path.start_at(in.program_pos());
    path.program = main.number;
    path.title = main.title;
    Axes lo{}, hi{};
    uint16_t mlo = 0, mhi = 0;
    if (scan_extremes(main, m.lathe && m.x_diameter, lo, hi, mlo, mhi))
        path.set_extremes(lo, hi, mlo, mhi);
}

}  // namespace

int plot(const PlotArgs& a) {
    PathPlane plane = PathPlane::xy;
    if (!plot_usage(a, plane)) return kUsage;
    MachineProfile m;
    if (!load_machine(batch_machine(a.machine), m)) return kUsage;
    ProgramMemory mem;
    if (int rc = load_all(a.files, mem)) return rc;
    const ProgramText* main = main_program(mem, a.files.front());
    if (!main) return kDataErr;
    workshop::Setup setup;
    if (!a.setup.empty() && !load_setup(a.setup, m, setup)) return kUsage;
    plan::EdgeLife life;
    for (const std::string& l : a.edge_life)
        if (std::string why = plan::read_edge_life(l, life); !why.empty()) {
            std::fprintf(stderr, tr("pupitre: --edge-life %s: %s\n"), l.c_str(), why.c_str());
            return kUsage;
        }
    life = edge_life(setup, life);
    Toolpath path(m);
    // The drawing takes the moves as they are made; the planner beside it
    // times them (the cycle time of the notes, the PDF's table of tools).
    plan::PlanSink planner(m);
    TeeSink both(path, planner);
    std::unique_ptr<workshop::Workshop> shop;
    if (!a.setup.empty()) {
        shop = std::make_unique<workshop::Workshop>(m, setup, &both);
        shop->draw_on_part(true);  // a C or B turn drawn on the part
    }
    RunOptions o;
    o.block_skip = a.block_skip;
    o.max_blocks = a.max_blocks;
    Interpreter in(m, mem, shop ? static_cast<MachineSink&>(*shop) : both, o);
    if (int rc = apply_sets(a.sets, in)) return rc;
    start_drawing(path, in, *main, m);
    int plane_seen = 0;
    in.start(main);
    run_collecting(in, path, plane_seen, shop.get());
    planner.finish();
    for (const Diag& d : in.diags()) {
        print_diag(d);
        path.add_error(d);
    }
    bool crashed = shop && shop->crashed();
    if (shop) draw_workshop(*shop, in, mem, a.files.front(), path);
    default_machine_note(a.machine, in.has_errors() || crashed);
    // A run that fails before any move has nothing to draw: no file is left
    // behind (docs/decisions.md, A failed run still plots). One that
    // fails later draws what ran.
    if (in.has_errors() && in.moves() == 0) {
        std::fputs(tr("pupitre: no drawing written: the program failed before its first move\n"),
                   stderr);
        return kProgramErrors;
    }
    SceneOptions so;
    so.plane = a.plane.empty() ? chosen_plane(path, m, plane_seen) : plane;
    so.machine = m.name;
    so.seconds = planner.clock();
    Scene scene = build_scene(path, so);
    for (const Output& out : kOutputs) {
        if ((a.*out.file).empty()) continue;
        if (out.file == &PlotArgs::pdf && !planner.report().tools.rows().empty()) {
            // The printed page has the table of each tool's time (issue 35).
            SceneOptions with = so;
            with.tools = planner.report().tools.rows();
            with.life = life;
            if (int rc = write_out(out, build_scene(path, with), a)) return rc;
        } else if (int rc = write_out(out, scene, a)) {
            return rc;
        }
    }
    return in.has_errors() || crashed ? kProgramErrors : kOk;
}

}  // namespace pupitre::cli
