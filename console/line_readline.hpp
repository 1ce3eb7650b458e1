// The input line with GNU readline, through its callback interface: readline
// edits, keeps the history and completes; it never reads the terminal or draws
// (the console feeds it bytes and shows rl_line_buffer itself).
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include "console/line_input.hpp"

namespace pupitre::console {

class ReadlineInput final : public LineInput {
  public:
    ReadlineInput();
    ~ReadlineInput() override;
    void feed(std::string_view bytes) override;
    std::string text() const override;
    int cursor() const override;
    void add_history(const std::string& line) override;
    void clear() override;
    void set_text(const std::string& text) override;
};

}  // namespace pupitre::console
