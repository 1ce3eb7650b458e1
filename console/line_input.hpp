// The input line behind an interface (ARCHITECTURE.md, Conventions): readline through its callback
// interface in the console, a plain fake in the tests.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace pupitre::console {

class LineInput {
  public:
    virtual ~LineInput() = default;
    // Bytes of the keys no binding took (text, editing keys, history keys).
    virtual void feed(std::string_view bytes) = 0;
    virtual std::string text() const = 0;
    virtual int cursor() const = 0;  // in columns
    virtual void add_history(const std::string& line) = 0;
    virtual void clear() = 0;
    // Puts a text on the line to be edited (the editor's "modify this block").
    virtual void set_text(const std::string& text) = 0;
    // A line was entered (Enter).
    std::function<void(const std::string&)> on_line;
    // Completion candidates for the word before the cursor (G/M codes, commands).
    std::function<std::vector<std::string>(std::string_view word)> complete;
    // A message for the user (the list of completions).
    std::function<void(const std::string&)> on_message;
};

// A minimal editor for tests and for terminals without readline: printable
// text, Backspace, Ctrl-U, Enter.
class PlainLineInput final : public LineInput {
  public:
    void feed(std::string_view bytes) override;
    std::string text() const override { return text_; }
    int cursor() const override;
    void add_history(const std::string& line) override { history_.push_back(line); }
    void clear() override { text_.clear(); }
    void set_text(const std::string& t) override { text_ = t; }
    const std::vector<std::string>& history() const { return history_; }

  private:
    std::string text_;
    std::vector<std::string> history_;
};

}  // namespace pupitre::console
