// The readline input line (see line_readline.hpp). Readline keeps global
// state, so one ReadlineInput exists at a time.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "console/line_readline.hpp"

#include <readline/history.h>
#include <readline/readline.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace pupitre::console {

namespace {

ReadlineInput* g_self = nullptr;
std::string g_bytes;  // what feed() gives readline, byte by byte
size_t g_pos = 0;
FILE* g_null = nullptr;
std::vector<std::string> g_found;  // completion candidates with their texts

int getc_hook(FILE*) {
    if (g_pos < g_bytes.size()) return static_cast<unsigned char>(g_bytes[g_pos++]);
    return EOF;  // never reached: feed() calls readline only while bytes remain
}

int input_available() {
    return g_pos < g_bytes.size();
}
void no_redisplay() {}
void no_prep(int) {}
void no_deprep() {}

void line_done(char* line) {
    if (!line) return;  // Ctrl-D on an empty line: nothing to do
    std::string s(line);
    std::free(line);
    if (g_self && g_self->on_line) g_self->on_line(s);
}

char* generator(const char* text, int state) {
    static size_t i;
    if (!state) i = 0;
    while (i < g_found.size()) {
        const std::string& f = g_found[i++];
        std::string word = f.substr(0, f.find(' '));
        (void)text;
        return strdup(word.c_str());
    }
    return nullptr;
}

char** attempt(const char* text, int, int) {
    rl_attempted_completion_over = 1;  // never complete file names
    g_found = g_self && g_self->complete ? g_self->complete(text) : std::vector<std::string>{};
    if (g_found.empty()) return nullptr;
    return rl_completion_matches(text, generator);
}

// Several candidates: listed on the message line, not printed by readline.
void show_matches(char**, int, int) {
    if (!g_self || !g_self->on_message) return;
    std::string all;
    for (const std::string& f : g_found) {
        if (!all.empty()) all += "   ";
        all += f;
    }
    g_self->on_message(all);
}

}  // namespace

ReadlineInput::ReadlineInput() {
    g_self = this;
    g_null = std::fopen("/dev/null", "w");
    rl_readline_name = "pupitre";
    rl_catch_signals = 0;
    rl_catch_sigwinch = 0;
    rl_change_environment = 0;
    rl_getc_function = getc_hook;
    rl_input_available_hook = input_available;
    rl_redisplay_function = no_redisplay;
    rl_prep_term_function = no_prep;
    rl_deprep_term_function = no_deprep;
    rl_outstream = g_null;
    rl_attempted_completion_function = attempt;
    rl_completion_display_matches_hook = show_matches;
    rl_completer_word_break_characters = const_cast<char*>(" \t");
    rl_variable_bind("bell-style", "none");
    using_history();
    stifle_history(500);
    rl_callback_handler_install("", line_done);
}

ReadlineInput::~ReadlineInput() {
    rl_callback_handler_remove();
    if (g_null) std::fclose(g_null);
    g_null = nullptr;
    g_self = nullptr;
}

void ReadlineInput::feed(std::string_view bytes) {
    g_bytes.assign(bytes);
    g_pos = 0;
    while (g_pos < g_bytes.size()) rl_callback_read_char();
}

std::string ReadlineInput::text() const {
    return rl_line_buffer ? std::string(rl_line_buffer) : std::string();
}

int ReadlineInput::cursor() const {
    if (!rl_line_buffer) return 0;
    int n = 0;
    for (int i = 0; i < rl_point && rl_line_buffer[i]; ++i)
        n += (static_cast<unsigned char>(rl_line_buffer[i]) & 0xc0) != 0x80;
    return n;
}

void ReadlineInput::add_history(const std::string& line) {
    ::add_history(line.c_str());
    // Readline set the history position when the current line began: move it
    // to the end, or the lines loaded from the store could not be reached.
    using_history();
}

void ReadlineInput::set_text(const std::string& text) {
    rl_replace_line(text.c_str(), 0);
    rl_point = rl_end;
}

void ReadlineInput::clear() {
    rl_replace_line("", 0);
    rl_point = rl_end = 0;
}

}  // namespace pupitre::console
