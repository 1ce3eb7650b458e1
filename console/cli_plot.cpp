// pupitre plot (see cli_plot.hpp): the same loading and dry run as `run`, with
// a Toolpath as the sink, then the SVG writer.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "console/cli_plot.hpp"

#include <png.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <vector>

#include "console/cli.hpp"
#include "core/interp.hpp"
#include "core/svg.hpp"
#include "core/toolpath.hpp"
#include "pages/page_graph.hpp"

namespace pupitre::cli {

namespace {

// Runs to the end as `run` does (stops are resumed), following the program's
// line types (E31000, E31001) and the first plane other than G17 it selects.
void run_collecting(Interpreter& in, Toolpath& path, int& plane_seen) {
    int rapid = -1, feed = -1;
    for (;;) {
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

PathPlane chosen_plane(const Toolpath& path, const MachineProfile& m, int plane_seen) {
    if (m.lathe || path.arc_plane() != 17 || !plane_seen) return path.default_plane();
    return plane_seen == 18 ? PathPlane::xz : plane_seen == 19 ? PathPlane::yz : PathPlane::xy;
}

int write_out(const std::string& name, const Toolpath& path, const SvgOptions& o) {
    std::FILE* f = name == "-" ? stdout : std::fopen(name.c_str(), "wb");
    if (!f) {
        std::fprintf(stderr, "pupitre: %s: cannot create: %s\n", name.c_str(),
                     std::strerror(errno));
        return kCantCreate;
    }
    bool ok = write_svg(path, o, f);
    int err = errno;
    if (f != stdout && std::fclose(f) != 0) ok = false;
    if (!ok) {
        std::fprintf(stderr, "pupitre: %s: cannot write: %s\n", name.c_str(), std::strerror(err));
        return kIoErr;
    }
    return kOk;
}

// libpng reports errors by longjmp: only plain data lives in this frame.
bool png_rows(std::FILE* f, int w, int h, const std::vector<uint8_t>& rgb) {
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!info) {
        png_destroy_write_struct(&png, nullptr);
        return false;
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return false;
    }
    png_init_io(png, f);
    png_set_IHDR(png, info, png_uint_32(w), png_uint_32(h), 8, PNG_COLOR_TYPE_RGB,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_text text[1];
    text[0].compression = PNG_TEXT_COMPRESSION_NONE;
    text[0].key = const_cast<char*>("Software");
    text[0].text = const_cast<char*>("pupitre plot");
    png_set_text(png, info, text, 1);
    png_write_info(png, info);
    for (int y = 0; y < h; ++y)
        png_write_row(png, const_cast<png_bytep>(rgb.data() + size_t(y) * size_t(w) * 3));
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    return true;
}

// The drawing rasterised one dot a pixel, in the SVG's colours.
std::vector<uint8_t> png_pixels(const Toolpath& path, PathPlane plane, int w, int& h) {
    int hx, vx;
    plane_axes(plane, hx, vx);
    PathBox b = path.bounds();
    if (b.empty()) b.add(path.start());
    double x0 = b.lo[hx], x1 = b.hi[hx], y0 = b.lo[vx], y1 = b.hi[vx];
    bool lathe = path.machine().lathe && plane == PathPlane::zx;
    if (lathe && !path.cut_bounds().empty()) y0 = std::min(y0, -path.cut_bounds().hi[vx]);
    double aspect = (y1 - y0 + 1e-9) / (x1 - x0 + 1e-9);
    h = std::clamp(int(w * aspect) / 4 * 4 + 8, 64, 4000);
    pages::DotRaster r;
    r.reset(w / 2, h / 4);
    pages::GraphView g;
    g.path = &path;
    g.plane = plane;
    pages::draw_graph(g, pages::fit_view(x0, y0, x1, y1, r.w(), r.h(), 8), r);
    static constexpr std::array<std::array<uint8_t, 3>, size_t(pages::Ink::count_)> kRgb = {{
        {255, 255, 255},
        {154, 154, 154},
        {200, 200, 200},
        {154, 154, 154},
        {51, 102, 204},
        {140, 140, 140},
        {26, 26, 26},
        {11, 122, 75},
        {217, 130, 0},
        {212, 0, 0},
    }};
    std::vector<uint8_t> rgb(size_t(r.w()) * size_t(r.h()) * 3, 255);
    for (int y = 0; y < r.h(); ++y)
        for (int x = 0; x < r.w(); ++x)
            if (r.test(x, y)) {
                const auto& c = kRgb[size_t(r.ink(x / 2, y / 4))];
                std::copy(c.begin(), c.end(), rgb.begin() + (ptrdiff_t(y) * r.w() + x) * 3);
            }
    h = r.h();
    return rgb;
}

int write_png(const std::string& name, const Toolpath& path, PathPlane plane, int width) {
    std::FILE* f = std::fopen(name.c_str(), "wb");
    if (!f) {
        std::fprintf(stderr, "pupitre: %s: cannot create: %s\n", name.c_str(),
                     std::strerror(errno));
        return kCantCreate;
    }
    int w = std::clamp(width, 64, 8000) / 2 * 2, h = 0;
    std::vector<uint8_t> rgb = png_pixels(path, plane, w, h);
    bool ok = png_rows(f, w, h, rgb);
    if (std::fclose(f) != 0) ok = false;
    if (!ok) {
        std::fprintf(stderr, "pupitre: %s: cannot write the PNG\n", name.c_str());
        return kIoErr;
    }
    return kOk;
}

}  // namespace

int plot(const PlotArgs& a) {
    PathPlane plane = PathPlane::xy;
    if (!a.plane.empty() && !parse_plane(a.plane, plane)) {
        std::fprintf(stderr, "pupitre: --plane %s: expected xy, xz, yz or zx\n", a.plane.c_str());
        return kUsage;
    }
    if ((a.svg.empty() && a.png.empty()) || a.files.empty()) {
        std::fprintf(stderr, "pupitre: plot needs --svg OUT (or --png OUT) and a program file\n");
        return kUsage;
    }
    MachineProfile m;
    if (!load_machine(batch_machine(a.machine), m)) return kUsage;
    ProgramMemory mem;
    if (int rc = load_all(a.files, mem)) return rc;
    const ProgramText* main = nullptr;
    for (const auto& p : mem.programs())
        if (p->file == a.files.front()) {
            main = p.get();
            break;
        }
    if (!main) {
        std::fprintf(stderr, "pupitre: %s: no program to run\n", a.files.front().c_str());
        return kDataErr;
    }
    Toolpath path(m);
    RunOptions o;
    o.block_skip = a.block_skip;
    o.max_blocks = a.max_blocks;
    Interpreter in(m, mem, path, o);
    if (int rc = apply_sets(a.sets, in)) return rc;
    path.start_at(in.program_pos());
    path.program = main->number;
    path.title = main->title;
    Axes lo{}, hi{};
    uint16_t mlo = 0, mhi = 0;
    if (scan_extremes(*main, m.lathe && m.x_diameter, lo, hi, mlo, mhi))
        path.set_extremes(lo, hi, mlo, mhi);
    int plane_seen = 0;
    in.start(main);
    run_collecting(in, path, plane_seen);
    for (const Diag& d : in.diags()) {
        print_diag(d);
        path.add_error(d);
    }
    default_machine_note(a.machine, in.has_errors());
    // A run that fails before any move has nothing to draw: no file is left
    // behind (CLARIFICATIONS 12.10). One that fails later draws what ran.
    if (in.has_errors() && in.moves() == 0) {
        std::fprintf(stderr, "pupitre: no drawing written: the program failed before its first move\n");
        return kProgramErrors;
    }
    SvgOptions so;
    so.plane = a.plane.empty() ? chosen_plane(path, m, plane_seen) : plane;
    so.machine = m.name;
    so.seconds = in.seconds();
    if (!a.svg.empty())
        if (int rc = write_out(a.svg, path, so)) return rc;
    if (!a.png.empty())
        if (int rc = write_png(a.png, path, so.plane, a.png_width)) return rc;
    return in.has_errors() ? kProgramErrors : kOk;
}

}  // namespace pupitre::cli
