// Real pictures in the terminal (see term_image.hpp).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "console/term_image.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <vector>

namespace pupitre::console {

namespace {

constexpr char kEsc = '\033';
constexpr uint32_t kQueryId = 31;

// The numbers of a CSI answer's parameters ("?62;4;22" -> 62 4 22).
std::vector<int> params(std::string_view s) {
    std::vector<int> out;
    while (!s.empty()) {
        while (!s.empty() && (s[0] < '0' || s[0] > '9')) s.remove_prefix(1);
        int v = 0;
        auto r = std::from_chars(s.data(), s.data() + s.size(), v);
        if (r.ptr == s.data()) break;
        out.push_back(v);
        s.remove_prefix(size_t(r.ptr - s.data()));
    }
    return out;
}

std::string base64(const uint8_t* p, size_t n) {
    static constexpr char kAlphabet[] =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((n + 2) / 3 * 4);
    for (size_t i = 0; i < n; i += 3) {
        const uint32_t v = uint32_t(p[i]) << 16 | (i + 1 < n ? uint32_t(p[i + 1]) << 8 : 0) |
                           (i + 2 < n ? p[i + 2] : 0);
        out += kAlphabet[(v >> 18) & 63];
        out += kAlphabet[(v >> 12) & 63];
        out += i + 1 < n ? kAlphabet[(v >> 6) & 63] : '=';
        out += i + 2 < n ? kAlphabet[v & 63] : '=';
    }
    return out;
}

std::string kitty(const render::Image& img, int cols, int rows, uint32_t id) {
    const auto* bytes = reinterpret_cast<const uint8_t*>(img.pixels().data());
    const std::string data = base64(bytes, img.pixels().size() * 4);
    std::string out = image_delete(ImageProtocol::kitty, id);
    const size_t chunk = 4096;
    for (size_t at = 0; at < data.size(); at += chunk) {
        out += kEsc;
        out += "_G";
        if (at == 0)
            out += "a=T,f=32,s=" + std::to_string(img.w()) + ",v=" + std::to_string(img.h()) +
                   ",c=" + std::to_string(cols) + ",r=" + std::to_string(rows) +
                   ",i=" + std::to_string(id) + ",q=2,C=1,";
        out += at + chunk < data.size() ? "m=1;" : "m=0;";
        out.append(data, at, chunk);
        out += kEsc;
        out += '\\';
    }
    return out;
}

// 6 levels of red and blue, 7 of green: 252 colours.
int sixel_index(render::Colour c) {
    const int r = int(render::red(c) * 5 + 127) / 255, g = int(render::green(c) * 6 + 127) / 255;
    const int b = int(render::blue(c) * 5 + 127) / 255;
    return r * 42 + g * 6 + b;
}

// One colour's line of a band: six pixels a character, runs repeated.
void sixel_line(const std::vector<uint8_t>& band, int w, int rows, int colour, std::string& out) {
    auto bits_at = [&](int x) {
        int bits = 0;
        for (int k = 0; k < rows; ++k)
            if (band[size_t(k) * size_t(w) + size_t(x)] == colour) bits |= 1 << k;
        return char(63 + bits);
    };
    out += '#' + std::to_string(colour);
    for (int x = 0; x < w;) {
        const char c = bits_at(x);
        int n = 1;
        while (x + n < w && bits_at(x + n) == c) ++n;
        if (n > 3)
            out += '!' + std::to_string(n) + c;
        else
            out.append(size_t(n), c);
        x += n;
    }
    out += '$';
}

std::string sixel(const render::Image& img) {
    std::string out = "\033P0;1;0q\"1;1;" + std::to_string(img.w()) + ";" + std::to_string(img.h());
    for (int i = 0; i < 252; ++i) {
        const int r = i / 42, g = (i / 6) % 7, b = i % 6;
        out += '#' + std::to_string(i) + ";2;" + std::to_string(r * 20) + ";" +
               std::to_string(g * 100 / 6) + ";" + std::to_string(b * 20);
    }
    std::vector<uint8_t> band(size_t(img.w()) * 6);
    for (int y0 = 0; y0 < img.h(); y0 += 6) {
        const int rows = std::min(6, img.h() - y0);
        std::array<bool, 252> used{};
        for (int k = 0; k < rows; ++k)
            for (int x = 0; x < img.w(); ++x) {
                const int c = sixel_index(img.at(x, y0 + k));
                band[size_t(k) * size_t(img.w()) + size_t(x)] = uint8_t(c);
                used[size_t(c)] = true;
            }
        for (int c = 0; c < 252; ++c)
            if (used[size_t(c)]) sixel_line(band, img.w(), rows, c, out);
        out += '-';
    }
    out += "\033\\";
    return out;
}

}  // namespace

std::string image_query(bool kitty) {
    std::string q;
    if (kitty) q += "\033_Gi=" + std::to_string(kQueryId) + ",s=1,v=1,a=q,t=d,f=24;AAAA\033\\";
    return q + "\033[16t\033[c";
}

ImageAnswer parse_answers(std::string_view s, std::string& rest) {
    ImageAnswer a;
    for (size_t i = 0; i < s.size();) {
        if (s[i] == kEsc && i + 1 < s.size() && s[i + 1] == '_') {  // APC: kitty's answer
            const size_t end = s.find("\033\\", i + 2);
            if (end == std::string_view::npos) break;
            const std::string_view body = s.substr(i + 2, end - i - 2);
            if (body.rfind("Gi=" + std::to_string(kQueryId) + ";OK", 0) == 0) a.kitty = true;
            i = end + 2;
            continue;
        }
        if (s[i] == kEsc && i + 1 < s.size() && s[i + 1] == '[') {
            size_t end = i + 2;
            while (end < s.size() && (s[end] < 0x40 || s[end] > 0x7e)) ++end;
            if (end >= s.size()) break;
            const std::string_view body = s.substr(i + 2, end - i - 2);
            if (s[end] == 'c' && !body.empty() && body[0] == '?') {
                a.done = true;
                const std::vector<int> p = params(body);
                a.sixel = std::find(p.begin() + (p.empty() ? 0 : 1), p.end(), 4) != p.end();
            } else if (s[end] == 't') {
                const std::vector<int> p = params(body);
                if (p.size() == 3 && p[0] == 6) a.cell_h = p[1], a.cell_w = p[2];
            } else {
                rest.append(s.substr(i, end + 1 - i));  // a key (an arrow, say)
            }
            i = end + 1;
            continue;
        }
        rest += s[i++];
    }
    return a;
}

std::string image_sequence(const render::Image& img, ImageProtocol p, int cols, int rows,
                           uint32_t id) {
    if (img.empty()) return {};
    if (p == ImageProtocol::kitty) return kitty(img, cols, rows, id);
    if (p == ImageProtocol::sixel) return sixel(img);
    return {};
}

std::string image_delete(ImageProtocol p, uint32_t id) {
    if (p != ImageProtocol::kitty) return {};
    return "\033_Ga=d,d=I,i=" + std::to_string(id) + ",q=2\033\\";
}

}  // namespace pupitre::console
