// The interpreter's named values: the settings (PREF.X, DEC1.Z, DEC3.Y, D1.R,
// L5, E80000) and the E parameters, read through the one table of corrector
// fields (value_name.hpp).
// SPDX-License-Identifier: GPL-3.0-or-later
#include <charconv>
#include <cmath>

#include "core/i18n.hpp"
#include "core/interp/value_name.hpp"

namespace pupitre {

namespace {
bool parse_double(std::string_view s, double& v) {
    auto r = std::from_chars(s.data(), s.data() + s.size(), v);
    return r.ec == std::errc() && r.ptr == s.data() + s.size();
}

// PREF.X, DEC1.Z, DEC3.Y: which origin (0, 1, 2) and the axis letter's index,
// or -1 when the name is not one of them.
int origin_named(std::string_view name, int& axis) {
    ValueName v;
    if (!parse_value_name(name, v) || v.kind != ValueName::Kind::origin) return -1;
    axis = v.axis;
    return v.number;
}
}  // namespace

std::string Interpreter::set(std::string_view name, double value, bool immediate) {
    int axis;
    if (int k = origin_named(name, axis); k >= 0) {
        if (!m_.has(axis)) return strf(tr("axis %c is not on %s"), name.back(), m_.name.c_str());
        Axes& which = k == 0 ? frames_.pref : k == 1 ? frames_.dec1 : frames_.dec3;
        which[size_t(axis)] = value;
        if (immediate) recompute_program_pos();
        return {};
    }
    if (name.size() >= 2 && name[0] == 'L') {
        double n;
        if (!parse_double(name.substr(1), n) || !LVars::valid(int(n)) || n != std::floor(n))
            return tr("no such L variable (L0-L19, L100-L199, L900-L959)");
        l_.v[size_t(n)] = value;
        l_.written.set(size_t(n));
        return {};
    }
    if (name.size() >= 2 && name[0] == 'E') {
        double n;
        if (!parse_double(name.substr(1), n) || n != std::floor(n))
            return tr("bad E parameter number");
        if (value != std::floor(value)) return tr("E parameters hold integers (internal units)");
        Error e = write_e(int(n), int64_t(value));
        e_written_.erase(int(n));  // a setting, not a write by the program
        return e.detail;
    }
    if (name.size() >= 4 && name[0] == 'D') return set_corrector(name, value);
    // TRANSLATORS: %s is an ellipsis (U+2026); msgids stay ASCII.
    return strf(tr("unknown setting (PREF.X, DEC1.Z, DEC3.Y, D1.R, L5, E80000%s)"), "\u2026");
}

// D<n>.<field> = value. A mill's C is E55xxx's only: no setting names it.
std::string Interpreter::set_corrector(std::string_view name, double value) {
    ValueName v;
    NameFault fault = parse_corrector_name(name, m_, v);
    if (fault == NameFault::number)
        return strf(tr("corrector must be D1 to D%d"), int(m_.correctors));
    const CorrField* field = fault == NameFault::none && v.field->settable ? v.field : nullptr;
    if (!field)
        return m_.lathe ? tr("lathe correctors have X Z R C DX DZ")
                        : tr("mill correctors have L R DL DR and the end radius A");
    // The Cazeneuve's gauges pilot the nose centre under the CNP (003:1912,
    // "régler les jauges de façon à piloter l'axe du rayon de l'outil"): its
    // correctors have no orientation, which is C0, the centre.
    if (!field->member && caz_ && value != 0)
        return tr("this controller's gauges pilot the nose centre (003:1912): no orientation C");
    Corrector& c = corr_[size_t(v.number)];
    if (field->member)
        c.*field->member = value;
    else
        c.c = int(value);
    // The active corrector's new gauge applies at the next move of each of
    // its axes (000:797, 000:843-865; pupitre-iso(5), DECISIONS); a new radius at the next G41/G42.
    if (v.number == modal_.d) {
        if (m_.lathe)
            gauge_pending_.set(X), gauge_pending_.set(Z);
        else
            gauge_pending_.set(size_t(modal_.tool_axis));
    }
    return {};
}

bool Interpreter::get(std::string_view name, double& out) const {
    int axis;
    if (int k = origin_named(name, axis); k >= 0) {
        out = (k == 0 ? frames_.pref : k == 1 ? frames_.dec1 : frames_.dec3)[size_t(axis)];
        return true;
    }
    ValueName v;
    if (parse_corrector_name(name, m_, v) == NameFault::none && v.field->settable) {
        const Corrector& c = corr_[size_t(v.number)];
        out = v.field->member ? c.*v.field->member : c.c;
        return true;
    }
    return false;
}

// ---- E parameters (000:7573-7735; pupitre-iso(5), E parameters) ----

Error Interpreter::e_rights(int n, bool write) const {
    auto ro = [&]() -> Error {
        if (!write) return {};
        return {95, strf(tr("E%d is read-only"), n)};
    };
    int type = n / 10000;
    int x = (n / 1000) % 10;  // axis index for E6x/E7x
    int k = n % 1000;
    if (n >= 10000 && n <= 10031) return {};
    if (n >= 20000 && n <= 20031) return ro();
    if (n >= 30000 && n <= 30127) return {};
    if (n >= 40000 && n <= 40127) return ro();
    if (n == 11000 || n == 11001 || n == 11003 || n == 11004 || n == 11005 || n == 11007 ||
        n == 11015)
        return {};
    if (n >= 21000 && n <= 21255) return ro();
    if (n == 31000 || n == 31001 || n == 32000) return {};
    if (n == 41000) return ro();
    if (n >= 50000 && n <= 50000) return ro();
    if (n == 51000 || n == 52000) return ro();
    if (type == 5 && k >= 1 && k <= 255 && n < 58000) return {};
    if (type == 6 && x <= 8 && k <= 5) return {};
    if (n == 69000) return {};
    if (type == 7 && x <= 8 && k <= 6) return (k == 5 || k == 6) ? Error{} : ro();
    if (n >= 79000 && n <= 79004) return n == 79003 ? Error{} : ro();
    if (n >= 80000 && n <= 80049) return {};
    if (n == 81000 || n == 82000) return {};
    if (n >= 90000 && n <= 93007 && (n % 1000) <= 7) return ro();
    return {91, strf(tr("E%d does not exist"), n)};
}

namespace {
int64_t um(double mm) {
    return int64_t(std::llround(mm * 1000.0));
}
double mm_of(int64_t v) {
    return double(v) / 1000.0;
}
}  // namespace

// An E access stops the block preparation: not under compensation (140) nor
// after an incomplete profile block (96) (000:7596-7642, 000:13236).
Error Interpreter::e_access() const {
    if (modal_.radcomp != 40)
        return {140, tr("E parameter access under radius compensation (G41/G42)")};
    if (pgp_.pending()) return {96, tr("E parameter access after an incomplete profile block")};
    return {};
}

Error Interpreter::read_e(int n, int64_t& out) {
    if (Error err = e_access()) return err;
    if (Error err = e_rights(n, false)) return err;
    // "Une opération sur un paramètre externe entraîne l'arrêt de mouvements
    // à la fin du bloc précédent" (000:7596).
    out_.exact_stop(loc_);
    out = e_value(n);
    return {};
}

// What E<n> reads (000:7573-7735; pupitre-iso(5), E parameters): the machine's state for
// the parameters that show it, else what was written or set.
int64_t Interpreter::e_value(int n) const {
    const int x = (n / 1000) % 10, k = n % 1000, type = n / 10000;
    switch (n) {
        case 11005:
            return (m_.lathe && m_.x_diameter && !modal_.radius_x) ? 1 : 0;
        case 11000:
            return frames_.ed != 0;
        case 11003:
            return frames_.mirror.any();
        case 11004:
            return frames_.scale_on;
        case 50000:
            return modal_.d;
        case 51000:
            return corr_[size_t(modal_.d)].c;
        case 52000:
            return um(corr_[size_t(modal_.d)].r);
        case 69000:
            return e_raw(n, 1000);
        case 32000:
            return e_raw(n, std::llround(m_.min_block_time * 1000.0));
        case 73000:
        case 74000:
            return 0;
        case 79001:
            return int64_t(std::llround(rpm_));
        case 79002:
            return 100;
        default:
            break;
    }
    if (n >= 21000 && n <= 21255) return 1;
    if (type == 5 && k >= 1 && k <= 255 && n < 56000) {
        const Corrector& c = corr_[size_t(k)];
        const CorrField* f = corr_field_of_e(x, m_.lathe);
        return f->member ? um(c.*f->member) : c.c;
    }
    if ((type == 6 && x <= 8 && k <= 5) || (type == 7 && x <= 8 && k <= 6)) return e_axis(n);
    return e_raw(n, 0);
}

// E6xxxx and E7xxxx: an axis's origins, travel limits and position.
int64_t Interpreter::e_axis(int n) const {
    const int x = (n / 1000) % 10, k = n % 1000, type = n / 10000;
    auto unit = [&](double v) { return is_rotary(x) ? int64_t(std::llround(v * 1e4)) : um(v); };
    const AxisConfig& lim = m_.axes[size_t(x)];
    if (type == 6) {
        const Axes* src[] = {&frames_.pref, &frames_.dec1, nullptr,
                             nullptr,       &frames_.dec3, &frames_.g59};
        if (src[k]) return unit((*src[k])[size_t(x)]);
        return e_raw(n, unit(k == 2 ? lim.min : lim.max));
    }
    if (k == 0 || k == 1) return unit(prog_[size_t(x)]);
    if (k == 2) return unit(lim.min);
    if (k == 3) return unit(lim.max);
    return e_raw(n, 0);
}

// What was written to E<n> or set, or `none`.
int64_t Interpreter::e_raw(int n, int64_t none) const {
    auto it = e_raw_.find(n);
    return it == e_raw_.end() ? none : it->second;
}

Error Interpreter::write_e(int n, int64_t value) {
    if (Error err = e_access()) return err;
    if (Error err = e_rights(n, true)) return err;
    if (value > INT32_MAX || value < INT32_MIN)
        return {92, strf(tr("value %lld does not fit an E parameter"), (long long)value)};
    out_.exact_stop(loc_);  // as a read (000:7596)
    int x = (n / 1000) % 10, k = n % 1000, type = n / 10000;
    auto from = [&](int axis) { return is_rotary(axis) ? double(value) / 1e4 : mm_of(value); };
    e_written_[n] = value;
    if (n == 11005) {
        if (m_.lathe && m_.x_diameter) modal_.radius_x = value == 0;
        return {};
    }
    if (type == 5 && k >= 1 && k <= 255 && n < 56000) {
        Corrector& c = corr_[size_t(k)];
        const CorrField* f = corr_field_of_e((n / 1000) % 10, m_.lathe);
        if (f->member)
            c.*f->member = mm_of(value);
        else
            c.c = int(value);
        if (k == modal_.d) gauge_pending_.set();
        return {};
    }
    if (type == 6 && x <= 8 && k <= 5 && k != 2 && k != 3) {
        Axes* dst[] = {&frames_.pref, &frames_.dec1, nullptr, nullptr, &frames_.dec3, &frames_.g59};
        (*dst[k])[size_t(x)] = from(x);
        recompute_program_pos();
        return {};
    }
    if (n == 32000) {  // milliseconds (pupitre-iso(5), E parameters)
        if (value < 0) return {92, tr("E32000, a time, may not be negative")};
        e_raw_[n] = value;
        min_block_ = double(value) / 1000.0;
        return {};
    }
    if (n == 69000) {
        if (value < 1 || value > 9999000)
            return {92, tr("scale factor E69000 must be 1 to 9999000 (0.001 to 9999)")};
        e_raw_[n] = value;
        frames_.scale = double(value) / 1000.0;
        recompute_program_pos();
        return {};
    }
    e_raw_[n] = value;
    if (type == 6 && (k == 2 || k == 3)) update_travel();
    return {};
}

}  // namespace pupitre
