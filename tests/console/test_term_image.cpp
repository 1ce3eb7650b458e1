// Real pictures in the terminal (issue 36): the answers to the console's
// queries decide; a terminal that answers DA1 only (tmux) takes none; keys
// typed meanwhile are kept; the pictures' sequences.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>

#include "console/term_image.hpp"

namespace pupitre::console {
namespace {

TEST(TermImage, TmuxAnswersDa1OnlyAndGetsCells) {
    std::string rest;
    const ImageAnswer a = parse_answers("\033[?1;2c", rest);
    EXPECT_TRUE(a.done);
    EXPECT_EQ(a.protocol(), ImageProtocol::none);
    EXPECT_EQ(rest, "");
}

TEST(TermImage, KittyAnswersItsQuery) {
    std::string rest;
    const ImageAnswer a = parse_answers("\033_Gi=31;OK\033\\\033[6;20;10t\033[?62;22c", rest);
    EXPECT_TRUE(a.done);
    EXPECT_EQ(a.protocol(), ImageProtocol::kitty);
    EXPECT_EQ(a.cell_w, 10);
    EXPECT_EQ(a.cell_h, 20);
    // An error is no answer.
    EXPECT_EQ(parse_answers("\033_Gi=31;ENOTSUPPORTED:x\033\\\033[?62c", rest).protocol(),
              ImageProtocol::none);
}

TEST(TermImage, SixelIsAttributeFourOfDa1) {
    std::string rest;
    EXPECT_EQ(parse_answers("\033[?62;4;6;22c", rest).protocol(), ImageProtocol::sixel);
    EXPECT_EQ(parse_answers("\033[?4;2c", rest).protocol(), ImageProtocol::none);  // 4 the class
}

TEST(TermImage, KeysTypedMeanwhileAreKept) {
    std::string rest;
    const ImageAnswer a = parse_answers("x\033[A\033[?1;2cy", rest);
    EXPECT_TRUE(a.done);
    EXPECT_EQ(rest, "x\033[Ay");
    rest.clear();
    EXPECT_FALSE(parse_answers("\033[?1;2", rest).done);  // not yet all there
}

TEST(TermImage, Sequences) {
    render::Image img;
    img.reset(12, 7, render::rgb(255, 0, 0));
    const std::string k = image_sequence(img, ImageProtocol::kitty, 3, 2, 1);
    EXPECT_EQ(k.rfind("\033_Ga=d,d=I,i=1,q=2\033\\\033_Ga=T,f=32,s=12,v=7,c=3,r=2,i=1,", 0), 0u)
        << k.substr(0, 80);
    EXPECT_EQ(k.substr(k.size() - 2), "\033\\");
    const std::string s = image_sequence(img, ImageProtocol::sixel, 3, 2, 1);
    EXPECT_EQ(s.rfind("\033P0;1;0q\"1;1;12;7", 0), 0u);
    EXPECT_NE(s.find("#210!12~$-"), std::string::npos) << s.substr(s.size() - 60);
    EXPECT_EQ(s.substr(s.size() - 2), "\033\\");
    EXPECT_EQ(image_sequence(img, ImageProtocol::none, 3, 2, 1), "");
}

}  // namespace
}  // namespace pupitre::console
