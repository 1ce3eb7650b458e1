// The WORKSHOP page (pupitre-setup(5)): the setup on the machine, the tool in
// use as it looks (never its true gauges: finding them is the setter's
// work), the probe's lamp, the shim, the crashes; the instruments and how to
// ask them (what is typed here is a request), and the readings taken.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <cmath>
#include <cstdio>
#include <span>
#include <string_view>

#include "core/workshop/workshop.hpp"
#include "pages/pages.hpp"

namespace pupitre::pages {

namespace {

struct InstrumentLine {
    const char* form;  // the request, as typed
    const char* name;  // N_(): the instrument
    const char* res;   // its resolution
    const char* what;  // N_(): what it reads
};
constexpr InstrumentLine kLathe[] = {
    {"dia Z-20", N_("micrometer"), "0.001", N_("the outside diameter")},
    {"bore Z-20", N_("bore gauge"), "0.001", N_("the inside diameter")},
    {"groove Z-5", N_("caliper"), "0.01", N_("the width of the groove whose bottom is there")},
    {"length", N_("depth gauge"), "0.01", N_("from the jaws' face to the part's face")},
    {"tool T1 X|Z|R", N_("presetter"), "0.001", N_("a tool's true gauge or nose radius, ±0.002")},
};
constexpr InstrumentLine kMill[] = {
    {"length X Y30 Z-5", N_("caliper"), "0.01", N_("the part's length along X (or Y) on a line")},
    {"width X X60 Y30 Z-5", N_("caliper"), "0.01",
     N_("the gap around a point along X (or Y): a pocket, a slot")},
    {"depth X60 Y30", N_("depth gauge"), "0.01", N_("from the top face down to the material")},
    {"height X60 Y30", N_("micrometer"), "0.001", N_("the part's thickness")},
    {"tool T1 L|R", N_("presetter"), "0.001", N_("a cutter's true length or radius, ±0.002")},
};

// The built-in setups' descriptions (data/setups), for the catalogue: shown
// in the console's language; a setup of one's own as it is written.
[[maybe_unused]] const char* const kSetupTexts[] = {
    N_("hydraulic three-jaw chuck, Ø60 bar sticking out 95 mm, front turret T1-T4, rear turret "
       "T11-T14"),
    N_("three-jaw chuck, Ø60 bar sticking out 95 mm, four tools"),
    N_("machine vice, 120 x 80 x 40 block, a tool setter, five tools"),
    N_("C rotary table and B head, fixture plate, 100 x 100 x 50 block, three tools")};

// A tool as the operator sees it on the turret or in the magazine: its
// nominal size and kind, to 0.1 mm.
std::string looks(const workshop::ToolTruth& t, bool mill) {
    char size[32];
    if (mill) {
        std::snprintf(size, sizeof size, "\u00d8%g", std::round(t.radius * 20) / 10);
        const char* kind = t.probe                       ? tr("probe")
                           : t.finder                    ? tr("edge finder")
                           : t.corner >= t.radius - 1e-9 ? tr("ball end")
                           : t.corner > 0                ? tr("bull nose")
                                                         : tr("end mill");
        return "T" + std::to_string(t.position) + " " + size + " " + kind;
    }
    std::snprintf(size, sizeof size, "r%g C%d", std::round(t.radius * 10) / 10, t.orientation);
    return "T" + std::to_string(t.position) + " " + (t.probe ? tr("probe") : size);
}

void machine_lines(const workshop::Workshop& w, const View& v, int width, std::vector<Line>& out) {
    const workshop::Setup& s = w.setup();
    const bool mill = w.is_mill();
    auto row = [&](const char* label, const std::string& text, Style st = Style::value) {
        out.push_back(Line{}.add(" " + pad(label, 11), Style::dim).add(text, st));
    };
    row(tr("Setup"), s.name + (s.description.empty() ? "" : ": " + tr_text(s.description)));
    const workshop::ToolTruth* t = w.setup().tool(w.tool());
    row(tr("In use"),
        t              ? looks(*t, mill)
        : w.tool() > 0 ? strf(tr("T%d: not in the setup (moves neither cut nor crash)"), w.tool())
                       : std::string(mill ? tr("no tool in the spindle") : tr("no tool: T0")));
    if (w.probe_in_use()) {
        const bool lit = w.probe_contact(v.sim->om());
        row(tr("Probe"), lit ? tr("\u25cf contact") : tr("\u25cb open"),
            lit ? Style::alarm : Style::value);
    }
    row(tr("Shim"), w.shim() > 0 ? strf(tr("%s mm on the part"), fmt_len(w.shim()).c_str())
                                 : std::string(tr("no shim on the part")));
    if (!mill && w.gauge_block() > 0)
        row(tr("Gauge"),
            strf(tr("%s mm block against the jaws' face"), fmt_len(w.gauge_block()).c_str()));
    row(tr("Crashes"), w.crashes().empty() ? std::string(tr("no crash"))
                                           : strf(tr("%zu, the last: %s"), w.crashes().size(),
                                                  w.crashes().back().what.c_str()));
    std::string tools;
    for (const workshop::ToolTruth& x : s.tools)
        tools += (tools.empty() ? "" : " \u00b7 ") + looks(x, mill);
    const std::vector<std::string> wrapped = wrap_text(tools, std::max(20, width - 14));
    for (size_t i = 0; i < wrapped.size(); ++i)
        row(i ? "" : tr("Tools"), wrapped[i], Style::normal);
}

// An instrument an exercise allows (`allowed` null or empty: every one), by
// the first word of its request.
bool allowed(const InstrumentLine& i, const std::vector<std::string>* allowed) {
    if (!allowed || allowed->empty()) return true;
    const std::string_view form(i.form);
    const std::string_view word = form.substr(0, form.find(' '));
    for (const std::string& a : *allowed)
        if (a == word) return true;
    return false;
}

// The instruments' words, for the catalogue: the page shows the request in
// the console's language, and the workshop reads both (instrument_word).
// TRANSLATORS: an instrument's word, typed on the WORKSHOP page: only diam,
// alésage, gorge, longueur, outil, largeur, profondeur and hauteur are read.
[[maybe_unused]] const char* const kWords[] = {N_("dia"),  N_("bore"),  N_("groove"), N_("length"),
                                               N_("tool"), N_("width"), N_("depth"),  N_("height")};

// "length X Y30 Z-5" with its word in the console's language.
std::string form_text(std::string_view form) {
    const size_t sp = form.find(' ');
    const std::string word(form.substr(0, sp));
    return tr_text(word) + std::string(sp == std::string_view::npos ? "" : form.substr(sp));
}

void instrument_lines(bool mill, const std::vector<std::string>* only, int width,
                      std::vector<Line>& out) {
    add_wrapped(out, Line{}.add(" "),
                mill ? tr("Instruments: type a request, Enter reads it (X Y Z from the "
                          "block's corner, Z from its top face)")
                     : tr("Instruments: type a request, Enter reads it (Z from the "
                          "part's right-hand face)"),
                width, Style::title);
    for (const InstrumentLine& i : mill ? std::span(kMill) : std::span(kLathe)) {
        if (!allowed(i, only)) continue;  // an exercise's forbidden ones are not offered
        std::string what = std::string(tr(i.name)) + " " + i.res + "  " + tr(i.what);
        add_wrapped(out, Line{}.add("   " + pad(form_text(i.form), 22), Style::value), what, width);
    }
}

}  // namespace

void page_shop(const View& v, Canvas& c, const Rect& r) {
    const workshop::Workshop* w = v.sim->shop();
    const bool mill = !v.sim->machine().lathe;
    // TRANSLATORS: the WORKSHOP page's title; WORKSHOP is the page's name.
    c.rule(r.y, w ? strf(tr("WORKSHOP  setup %s"), w->setup().name.c_str())
                  : std::string(tr("WORKSHOP")));
    std::vector<Line> lines;
    const int width = r.w - 1;
    if (!w) {
        add_wrapped(lines, Line{}.add(" "),
                    mill ? tr("No workshop: the machine moves a point. :setup mill puts "
                              "a block in the vice.")
                         : tr("No workshop: the machine moves a point. :setup lathe "
                              "puts a bar in the chuck."),
                    width, Style::dim);
        draw_lines(lines, v.scroll, c, Rect{r.x, r.y + 1, r.w, r.h - 1});
        return;
    }
    machine_lines(*w, v, r.w, lines);
    // The readings before the instruments' table: the newest is what the
    // operator looks for, on the first screen.
    lines.push_back(Line{});
    lines.push_back(Line{}.add(" " + std::string(tr("Readings (newest first)")), Style::title));
    if (!v.readings || v.readings->empty())
        lines.push_back(Line{}.add("   " + std::string(tr("none yet")), Style::dim));
    else
        for (const std::string& s : *v.readings) add_wrapped(lines, Line{}.add("   "), s, width);
    lines.push_back(Line{});
    instrument_lines(w->is_mill(), v.instruments, width, lines);
    lines.push_back(Line{});
    add_wrapped(lines, Line{}.add(" "),
                tr(":part new fresh stock, :part export FILE, :shim MM|off the paper "
                   "test, :setup NAME|off"),
                width, Style::dim);
    draw_lines(lines, v.scroll, c, Rect{r.x, r.y + 1, r.w, r.h - 1});
}

}  // namespace pupitre::pages
