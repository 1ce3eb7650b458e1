// Program files as the batch commands load them (ProgramMemory::load_file):
// a large file is mapped rather than read (core/parse/text.hpp, issue 14),
// and must run, split and change exactly as the same text read into memory.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "tests/unit/helpers.hpp"

using namespace pupitre;
namespace fs = std::filesystem;

namespace {

// A file of at least `bytes`: %1 with a G76 field and moves, then %2.
std::string big_program(size_t bytes) {
    std::string t = "%1 (BIG)\nN10 G76 H1 N20\nN20 L1=1          \nN30 G1 F500 X0 Y0\n";
    for (int i = 0; t.size() < bytes; ++i)
        t += "N" + std::to_string(40 + i % 90000) + " X" + std::to_string(i % 97) + " Y" +
             std::to_string(i % 13) + ".5\n";
    return t + "N99 L1=7\nN100 G76 H1 N20\nM2\n%2\nG0 X5\n";
}

struct TempFile {
    fs::path path;
    explicit TempFile(const std::string& text) {
        path = fs::temp_directory_path() / ("pupitre_map_" + std::to_string(getpid()) + ".iso");
        std::ofstream(path, std::ios::binary) << text;
    }
    ~TempFile() { fs::remove(path); }
};

std::vector<std::array<double, 2>> run_moves(ProgramMemory& mem, double& l1) {
    MachineProfile m;
    builtin_machine("mill", m);
    test::Capture cap;
    Interpreter in(m, mem, cap);
    in.start(mem.first());
    in.run_to_end();
    EXPECT_FALSE(in.has_errors());
    l1 = in.lvars().v[1];
    std::vector<std::array<double, 2>> out;
    for (const auto& e : cap.moves) out.push_back({e.to_prog[X], e.to_prog[Y]});
    return out;
}

}  // namespace

TEST(ProgramFile, ALargeFileIsMappedAndRunsAsTheSameTextInMemory) {
    const std::string text = big_program(ProgramMemory::kMapFrom + 1000);
    TempFile f(text);
    ProgramMemory mapped, read;
    std::optional<Diag> d = mapped.load_file(f.path);
    ASSERT_FALSE(d) << d->detail;
    d = read.load_text("same", text);
    ASSERT_FALSE(d) << d->detail;
    ASSERT_EQ(mapped.programs().size(), 2u);
    const ProgramText* p1 = mapped.find(1);
    const ProgramText* p2 = mapped.find(2);
    ASSERT_TRUE(p1 && p2);
    EXPECT_TRUE(p1->text->mapped());
    EXPECT_EQ(p1->title, "BIG");
    EXPECT_EQ(p2->first_line, read.find(2)->first_line);
    EXPECT_EQ(p2->body(), "G0 X5\n");
    // The run writes L1 into N20 twice (G76): the mapped text becomes a string.
    double l1_mapped = 0, l1_read = 0;
    const auto a = run_moves(mapped, l1_mapped);
    const auto b = run_moves(read, l1_read);
    EXPECT_GT(a.size(), 30000u);
    EXPECT_EQ(a, b);
    EXPECT_EQ(l1_mapped, 7);
    EXPECT_FALSE(p1->text->mapped());
    EXPECT_NE(p1->body().find("N20 L1=7 "), std::string_view::npos);
    EXPECT_EQ(p1->body(), read.find(1)->body());
}

TEST(ProgramFile, ALargeFileWithoutItsLastNewlineIsReadAndEndsWithOne) {
    std::string text = big_program(ProgramMemory::kMapFrom + 10);
    text.pop_back();
    TempFile f(text);
    ProgramMemory mem;
    const std::optional<Diag> d = mem.load_file(f.path);
    ASSERT_FALSE(d) << d->detail;
    const ProgramText* p2 = mem.find(2);
    ASSERT_TRUE(p2);
    EXPECT_FALSE(p2->text->mapped());
    EXPECT_EQ(p2->body(), "G0 X5\n");
}

TEST(ProgramFile, ALargeBinaryFileIsRefusedAsNotText) {
    std::string text = big_program(ProgramMemory::kMapFrom + 10);
    text[text.size() / 2] = '\0';
    TempFile f(text);
    ProgramMemory mem;
    const std::optional<Diag> d = mem.load_file(f.path);
    ASSERT_TRUE(d);
    EXPECT_EQ(d->code, err::kNotText);
    EXPECT_TRUE(mem.programs().empty());
}

TEST(ProgramFile, ASplicedMappedTextKeepsItsProgramsInPlace) {
    TempFile f(big_program(ProgramMemory::kMapFrom));
    ProgramMemory mem;
    const std::optional<Diag> d = mem.load_file(f.path);
    ASSERT_FALSE(d) << d->detail;
    const ProgramText* p1 = mem.find(1);
    const ProgramText* p2 = mem.find(2);
    const int line2 = p2->first_line;
    const std::string_view before = p1->body();  // a view of the mapping
    const Splice s = mem.splice(p1, p1->begin, 0, "N1 G0 X1\nN2 G0 X2\n");
    EXPECT_EQ(s.ins_lines, 2);
    EXPECT_FALSE(p1->text->mapped());
    EXPECT_EQ(p1->body().substr(0, 18), "N1 G0 X1\nN2 G0 X2\n");
    EXPECT_EQ(p2->first_line, line2 + 2);
    EXPECT_EQ(p2->body(), "G0 X5\n");
    EXPECT_EQ(before.substr(0, 15), "N10 G76 H1 N20\n");  // still readable
}

TEST(ProgramFile, ASmallFileIsRead) {
    TempFile f("%5\nG0 X1\n");
    ProgramMemory mem;
    const std::optional<Diag> d = mem.load_file(f.path);
    ASSERT_FALSE(d) << d->detail;
    ASSERT_TRUE(mem.find(5));
    EXPECT_FALSE(mem.find(5)->text->mapped());
}

// A file is split at its header lines: a line whose first non-blank
// character is '%' (a '%' in a comment is none); the text before the first
// header is program 0 only when a line of it is a block.
TEST(ProgramFile, AFileIsSplitAtItsHeaderLinesOnly) {
    ProgramMemory mem;
    ASSERT_FALSE(
        mem.load_text("f.iso", "(SHOP 50%)\n\n  %7.2 (SEVEN)\nN10 G0 X1 (100%)\n%8\nG0 X2"));
    ASSERT_EQ(mem.programs().size(), 2u);
    const ProgramText* p7 = mem.find(7);
    const ProgramText* p8 = mem.find(8);
    ASSERT_TRUE(p7 && p8);
    EXPECT_EQ(p7->index, 2);
    EXPECT_EQ(p7->title, "SEVEN");
    EXPECT_EQ(p7->first_line, 4);
    EXPECT_EQ(p7->body(), "N10 G0 X1 (100%)\n");
    EXPECT_EQ(p8->first_line, 6);
    EXPECT_EQ(p8->body(), "G0 X2\n");
    ProgramMemory with0;
    ASSERT_FALSE(with0.load_text("g.iso", "G0 X5\n%3\nG0 X6\n"));
    ASSERT_EQ(with0.programs().size(), 2u);
    EXPECT_EQ(with0.programs()[0]->number, 0);
    EXPECT_EQ(with0.programs()[0]->body(), "G0 X5\n");
    EXPECT_EQ(with0.find(3)->first_line, 3);
}

// A pipe (or a terminal) is read to its end.
TEST(ProgramFile, APipeIsReadToItsEnd) {
    int fds[2];
    ASSERT_EQ(pipe(fds), 0);
    const std::string text = "%9\nG0 X1\n";
    ASSERT_EQ(write(fds[1], text.data(), text.size()), ssize_t(text.size()));
    close(fds[1]);
    ProgramMemory mem;
    const std::optional<Diag> d = mem.load_file("/proc/self/fd/" + std::to_string(fds[0]));
    EXPECT_FALSE(d) << d->detail;
    close(fds[0]);
    ASSERT_TRUE(mem.find(9));
    EXPECT_EQ(mem.find(9)->body(), "G0 X1\n");
}
