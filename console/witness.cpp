// The Cazeneuve lathe's tool setting from a witness cut (seed 003:802-808):
// "à partir d'un usinage témoin quelconque réalisé en manuel en venant
// tangenter avec chacun des outils", the computer works out each tool's
// setting. The setter turns a diameter and a face by hand, reads the
// diameter with the micrometer and gives both once (:witness); then each
// tool in turn touches the witness (tangenter) and :tangent X or Z sets its
// corrector so that its point reads the witness. Any lathe may use it: on a
// NUM it is :measure with the surface remembered.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <cmath>
#include <cstdio>

#include "console/setting.hpp"
#include "core/i18n.hpp"
#include "store/store.hpp"

namespace pupitre::console {

std::string SettingDesk::witness_text() const {
    if (!witness_.set) return {};
    return strf(tr("witness cut: \u00f8%s, face at Z %s"), pages::fmt_len(witness_.dia).c_str(),
                pages::fmt_len(witness_.face).c_str());
}

void SettingDesk::load_witness() {
    witness_ = Witness{};
    if (!b_.store()) return;
    auto r = b_.store()->setting("witness." + b_.store_key());
    if (r.error || !r.value || r.value->empty()) return;
    witness_.set = std::sscanf(r.value->c_str(), "%lf %lf", &witness_.dia, &witness_.face) == 2 &&
                   witness_.dia > 0;
}

void SettingDesk::save_witness() {
    if (!b_.store()) return;
    b_.store()->set_setting("witness." + b_.store_key(),
                            witness_.set ? strf("%.4f %.4f", witness_.dia, witness_.face) : "");
}

// :witness DIA [FACE] (commands.cpp reads the words): the witness's
// diameter, read with the micrometer, and the program Z of its face (0: the
// program's origin is on the face). dia <= 0: forget it; NaN: say it.
Effect SettingDesk::witness(double dia, double face) {
    if (!b_.machine().lathe) {
        b_.say(tr(":witness: a lathe's tool setting (the witness is a turned diameter and face)"),
               true);
    } else if (std::isnan(dia)) {
        b_.say(witness_.set ? witness_text()
                            : std::string(tr("no witness cut: :witness DIA [FACE], e.g. "
                                             ":witness 58.02 0")));
    } else if (dia <= 0) {
        witness_ = Witness{};
        save_witness();
        b_.say(tr("witness cut forgotten"));
    } else {
        witness_ = Witness{true, dia, face};
        save_witness();
        b_.say(witness_text() + "; " + tr("then :tangent X|Z with each tool"));
    }
    return Effect::redraw;
}

// :tangent X|Z: the active tool touches the witness's diameter (X) or face
// (Z); its corrector is set so that the tool's point reads the witness.
Effect SettingDesk::tangent(int axis) {
    if (!witness_.set) {
        b_.say(tr(":tangent: no witness cut yet: turn a diameter and a face, measure the "
                  "diameter, then :witness DIA [FACE]"),
               true);
        return Effect::redraw;
    }
    if (b_.sim().corrector() == 0) {
        b_.say(strf(tr(":tangent: T%d has no corrector (D0): select the tool with its corrector "
                       "first"),
                    b_.sim().tool()),
               true);
        return Effect::redraw;
    }
    // The surface as the program writes it: X a radius or a diameter. The
    // Cazeneuve's rear turret, positions 11-14 (003:1028-1030), touches the
    // witness behind the axis, at X < 0 (003:1563).
    const bool rear = b_.machine().dialect == Dialect::cazeneuve && b_.sim().tool() >= 11;
    const double surface =
        axis == Z ? witness_.face : b_.sim().to_display(X, (rear ? -1 : 1) * witness_.dia / 2);
    return measure(b_.sim().corrector(), axis, surface);
}

}  // namespace pupitre::console
