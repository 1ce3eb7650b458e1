// The JSON that pupitre writes: numbers with 4 decimals, strings escaped.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "core/output/json.hpp"

#include <cmath>
#include <cstdio>

namespace pupitre {

void append_fixed4(std::string& out, double v) {
    if (std::fabs(v) < 0.00005) v = 0;
    char buf[64];
    int n = std::snprintf(buf, sizeof buf, "%.4f", v);
    out.append(buf, size_t(n));
}

void append_json_string(std::string& out, std::string_view text) {
    out += '"';
    for (char c : text) {
        switch (c) {
            case '"':
                out += "\\\"";
                break;
            case '\\':
                out += "\\\\";
                break;
            case '\n':
                out += "\\n";
                break;
            case '\t':
                out += "\\t";
                break;
            default:
                if (static_cast<unsigned char>(c) < 0x20) {
                    char buf[8];
                    std::snprintf(buf, sizeof buf, "\\u%04x", c);
                    out += buf;
                } else {
                    out += c;
                }
        }
    }
    out += '"';
}

}  // namespace pupitre
