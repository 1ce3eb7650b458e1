// The store as a run sees it: stored programs called with G77 H, correctors and
// origins seeded into the interpreter, and the program's writes kept.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "store/link.hpp"
#include "store_helpers.hpp"

using namespace pupitre;
using namespace pupitre::store;
using test::TempDir;

namespace {

struct Null final : MachineSink {};

struct StoreRun {
    MachineProfile m;
    ProgramMemory mem;
    Null sink;
    std::unique_ptr<Interpreter> in;
    StoreRun(Store& s, const std::string& machine, const std::string& text) {
        builtin_machine(machine, m);
        mem.load_text("main.iso", text);
        EXPECT_FALSE(load_programs(s, mem).error);
        in = std::make_unique<Interpreter>(m, mem, sink);
        EXPECT_FALSE(seed_machine(s, *in).error);
        in->start(mem.first());
        in->run_to_end();
    }
    double L(int n) const { return in->lvars().v[size_t(n)]; }
    int error() const {
        for (const Diag& d : in->diags())
            if (d.is_error()) return d.code;
        return 0;
    }
};

}  // namespace

using StoreLink = test::OnBothEngines;
PUPITRE_ON_BOTH_ENGINES(StoreLink);

TEST_P(StoreLink, StoredProgramsAreProgramMemory) {
    test::Place t(GetParam());
    auto s = test::open_store(t / "l.db");
    ASSERT_TRUE(s->save(900, "L1=L1+1\nL2=7\n", kNew, "").ok());  // a fragment: no % line
    ASSERT_TRUE(s->save(901, "(LEADER)\n%901\nL3=3\n", kNew, "").ok());
    ASSERT_TRUE(s->save(902, "%902\nL4=1\n", kNew, "").ok());
    s->remove(902);
    ProgramMemory mem;
    mem.load_text("mine.iso", "%300\nL9=9\n");  // a file on the command line wins
    auto n = load_programs(*s, mem);
    ASSERT_TRUE(n.ok());
    EXPECT_EQ(n.value, 3);  // %301, %900, %901; not %300, not the deleted %902
    EXPECT_EQ(mem.find(300)->file, "mine.iso");
    const ProgramText* frag = mem.find(900);
    ASSERT_TRUE(frag);
    EXPECT_EQ(frag->file, "store:%900");
    EXPECT_EQ(frag->first_line, 1);
    EXPECT_EQ(frag->body(), "L1=L1+1\nL2=7\n");
    EXPECT_FALSE(mem.find(902));

    StoreRun r(*s, "mill", "%1\nL1=0\nG77 H900\nG77 H901\nM2\n");
    EXPECT_EQ(r.error(), 0);
    EXPECT_EQ(r.L(1), 1);
    EXPECT_EQ(r.L(2), 7);
    EXPECT_EQ(r.L(3), 3);
}

TEST_P(StoreLink, DiagnosticsInAStoredFragmentNameItsLine) {
    test::Place t(GetParam());
    auto s = test::open_store(t / "l.db");
    ASSERT_TRUE(s->save(910, "L1=1\nG77 H999\n", kNew, "").ok());
    StoreRun r(*s, "mill", "%1\nG77 H910\nM2\n");
    ASSERT_FALSE(r.in->diags().empty());
    const Diag& d = r.in->diags().front();
    EXPECT_EQ(d.code, 25);
    EXPECT_EQ(d.file, "store:%910");
    EXPECT_EQ(d.line, 2);
}

TEST_P(StoreLink, SeedsCorrectorsAndOriginsOfTheMachine) {
    test::Place t(GetParam());
    auto s = test::open_store(t / "l.db");
    ASSERT_TRUE(s->set_values("lathe",
                              {{"D1.X", 15157},
                               {"D1.Z", 42126},
                               {"D3.C", 3},
                               {"D3.DX", -20},
                               {"PREF.X", 12235},
                               {"DEC1.Z", -500},
                               {"DEC3.Z", 250},
                               {"PREF.Y", 1},
                               {"D2.L", 9}},  // not lathe things
                              "")
                    .ok());
    ASSERT_TRUE(s->set_values("mill", {{"D1.L", 143030}}, "").ok());
    StoreRun r(*s, "lathe",
               "%1\nL1=E50001\nL2=E51001\nL3=E55003\nL4=E53003\nL5=E60000\nL6=E62001\nL7=E62004\n"
               "L8=E50002\nM2\n");
    EXPECT_EQ(r.error(), 0);
    EXPECT_EQ(r.L(1), 15157);
    EXPECT_EQ(r.L(2), 42126);
    EXPECT_EQ(r.L(3), 3);
    EXPECT_EQ(r.L(4), -20);
    EXPECT_EQ(r.L(5), 12235);
    EXPECT_EQ(r.L(6), -500);
    EXPECT_EQ(r.L(7), 250);
    EXPECT_EQ(r.L(8), 0);
    // Nothing the program only read is written back.
    EXPECT_TRUE(persistent_writes(*r.in).empty());
    // The values applied, by name: the mill's and the lathe-less ones are not.
    auto m = seed_machine(*s, *r.in).value;
    EXPECT_EQ(m.size(), 7u);
    EXPECT_FALSE(m.count("PREF.Y"));
    EXPECT_FALSE(m.count("D2.L"));
}

TEST_P(StoreLink, ProgramWritesPersistWithAnAudit) {
    test::Place t(GetParam());
    auto s = test::open_store(t / "l.db");
    ASSERT_TRUE(s->set_values("lathe", {{"D1.X", 1000}}, "page CORR").ok());
    // Program %555 of the handbook loads tool gauges by program (000:7573-7735).
    StoreRun r(
        *s, "lathe",
        "%555\nE50001=15157\nE51001=42126\nE50003=13589\nE55003=2\nE53003=-40\nE60000=12235\n"
        "E62001=-100\nE62004=50\nE60005=7\nE80000=18\nE62002=-700000\nM2\n");
    EXPECT_EQ(r.error(), 0);
    auto w = persistent_writes(*r.in);
    std::vector<std::pair<std::string, int64_t>> want{
        {"D1.X", 15157}, {"D3.X", 13589},   {"D1.Z", 42126},  {"D3.DX", -40},
        {"D3.C", 2},     {"PREF.X", 12235}, {"DEC1.Z", -100}, {"DEC3.Z", 50}};
    EXPECT_EQ(w, want);  // not G59 (E60005), not E80000, not the travel limit E62002
    auto c = persist_run(*s, *r.in, "program %555 (tools.iso)");
    ASSERT_TRUE(c.ok()) << c.error.message;
    ASSERT_EQ(c.value.size(), want.size());
    EXPECT_EQ(*c.value[0].old_value, 1000);
    EXPECT_FALSE(c.value[1].old_value);
    auto a = s->audit("lathe").value;
    ASSERT_EQ(a.size(), 1 + want.size());
    EXPECT_EQ(a.back().source, "program %555 (tools.iso)");
    EXPECT_EQ(a[1].name, "D1.X");
    EXPECT_EQ(*a[1].old_value, 1000);
    EXPECT_EQ(*a[1].new_value, 15157);
    // The next run starts from them.
    StoreRun again(*s, "lathe", "%2\nL1=E51001\nL2=E62004\nM2\n");
    EXPECT_EQ(again.L(1), 42126);
    EXPECT_EQ(again.L(2), 50);
}

TEST_P(StoreLink, MillFieldsAndRotaryOrigins) {
    test::Place t(GetParam());
    auto s = test::open_store(t / "l.db");
    StoreRun r(
        *s, "mill5",
        "%1\nE50002=143030\nE51002=500\nE52002=6000\nE53002=-10\nE54002=-20\nE68000=1801203\nM2\n");
    EXPECT_EQ(r.error(), 0);
    auto w = persistent_writes(*r.in);
    std::vector<std::pair<std::string, int64_t>> want{{"D2.L", 143030}, {"D2.A", 500},
                                                      {"D2.R", 6000},   {"D2.DL", -10},
                                                      {"D2.DR", -20},   {"PREF.C", 1801203}};
    EXPECT_EQ(w, want);
    ASSERT_TRUE(persist_run(*s, *r.in, "t").ok());
    StoreRun again(*s, "mill5", "%2\nL1=E51002\nL2=E68000\nM2\n");
    EXPECT_EQ(again.L(1), 500);
    EXPECT_EQ(again.L(2), 1801203);
    EXPECT_EQ(format_value("PREF.C", 1801203), "180.1203");
    EXPECT_EQ(format_value("DEC1.X", -1500), "-1.500");
    EXPECT_EQ(format_value("D3.C", 2), "2");
    EXPECT_EQ(format_value("D3.DX", 40), "0.040");
}
