// The setting desk (console/setting.cpp, console/witness.cpp): the setter's
// work on the PREF and CORR pages, touch-off, tool measurement, the origins
// changed during a run that wait for the next move, undo, the memory-protect
// key and the Cazeneuve's witness cut. Values in mm as --set names them (X of
// origins and gauges a radius); every change is stored with an audit row.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "console/desk.hpp"

namespace pupitre::console {

class SettingDesk {
  public:
    explicit SettingDesk(Bench& b) : b_(b) {}
    // The protection key and the witness cut as the store keeps them.
    void load();

    // NAME = value from `source` (the audit's): false when refused (said).
    bool apply(const std::string& name, double value, const std::string& source);
    // Text typed on the PREF or CORR page.
    Effect text(std::string_view typed);
    Effect touch(int axis, double surface);  // asks first with no corrector (D0)
    Effect measure(int d, int axis, double surface);
    Effect undo();
    Effect protect_command(std::string_view args);  // :protect, the LOCK key
    bool unprotected(std::string_view what);        // says why when protected
    // The Cazeneuve's tool setting from a witness cut: :witness DIA [FACE]
    // once, then :tangent X|Z with each tool.
    Effect witness(double dia, double face);  // dia <= 0: forget it; NaN: say it
    Effect tangent(int axis);                 // X or Z

    bool locked() const { return protect_; }
    // A replay's (record.hpp): the protection as the student's console had
    // it, which the store it read and its PIN decided.
    void set_locked(bool on) { protect_ = on; }
    size_t undo_depth() const { return undo_.size(); }
    // The corrector the CORR page edits: :measure Dn chooses it as typed,
    // the page's keys within D1 to the last.
    int corrector() const { return corr_cursor_; }
    void choose_corrector(int d) { corr_cursor_ = d; }
    void move_corrector(int delta);

    // The PREF and CORR pages' part of a frame.
    void view(pages::View& v) const;

  private:
    Effect touch_now(int axis, double surface);
    std::string implausible_gauge(const std::string& name, double value) const;
    void echo_comma(std::string_view typed, double v);
    // Origins changed during a run that wait for the next move.
    std::vector<std::string> pending_origins() const;
    std::string witness_text() const;  // "" when none
    void load_witness();
    void save_witness();

    Bench& b_;
    bool protect_ = false;
    int corr_cursor_ = 1;
    std::string last_setting_;  // the PREF and CORR pages show its arithmetic
    struct Undo {
        std::string name;
        double old = 0;
    };
    std::vector<Undo> undo_;
    std::map<std::string, long> pending_origin_;  // name -> interpreter moves when set
    struct Witness {
        bool set = false;
        double dia = 0, face = 0;  // mm: the diameter read, the face's program Z
    } witness_;
};

}  // namespace pupitre::console
