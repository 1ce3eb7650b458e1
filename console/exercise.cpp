// Training in the console (see exercise.hpp): the class's key, the attempt
// on a hidden setup, :submit and the report.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "console/exercise.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string_view>

#include "console/record.hpp"
#include "console/refusal.hpp"
#include "core/digest.hpp"
#include "core/i18n.hpp"
#include "core/workshop/workshop.hpp"
#include "store/store.hpp"

namespace pupitre::console {

namespace {

std::string read_file(const std::string& path, bool& ok) {
    std::ifstream f(path, std::ios::binary);
    ok = bool(f);
    std::stringstream ss;
    if (ok) ss << f.rdbuf();
    return ss.str();
}

std::string to_hex(std::string_view bytes) {
    std::string out;
    char h[3];
    for (unsigned char c : bytes) {
        std::snprintf(h, sizeof h, "%02x", c);
        out += h;
    }
    return out;
}

// A keystream from SHA-256 of the seed and a counter, XORed in, as hex.
std::string keystream_xor(const std::string& in, uint64_t seed) {
    std::string out = in, block;
    for (size_t i = 0; i < out.size(); ++i) {
        if (i % 32 == 0) {
            std::string h = sha256_hex(std::to_string(seed) + ":" + std::to_string(i / 32));
            block.clear();
            for (size_t k = 0; k < 64; k += 2)
                block += char(std::stoi(h.substr(k, 2), nullptr, 16));
        }
        out[i] = char(out[i] ^ block[i % 32]);
    }
    return out;
}

}  // namespace

std::string class_key_path() {
    if (const char* k = std::getenv("PUPITRE_CLASS_KEY"); k && *k) return k;
    if (const char* x = std::getenv("XDG_CONFIG_HOME"); x && *x == '/')
        return std::string(x) + "/pupitre/class.key";
    if (const char* h = std::getenv("HOME"); h && *h)
        return std::string(h) + "/.config/pupitre/class.key";
    return {};
}

namespace {

// A key file read into `key`, made (0600, 32 random bytes in hex) when it
// does not exist and `create`. "" or what went wrong.
std::string key_file(const std::string& path, bool create, std::string& key) {
    bool ok = false;
    std::string text = read_file(path, ok);
    if (ok) {
        while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
        if (text.size() < 16) return strf(tr("the class key %s is too short"), path.c_str());
        key = text;
        return {};
    }
    if (!create)
        return strf(tr("no class key at %s: the teacher's key is needed (PUPITRE_CLASS_KEY)"),
                    path.c_str());
    std::string fresh = random_hex(32);
    if (fresh.empty()) return tr("the system gave no random bytes for the class key");
    std::error_code ec;
    std::filesystem::create_directories(std::filesystem::path(path).parent_path(), ec);
    int fd = open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0600);
    if (fd < 0)
        return strf(tr("cannot create the class key %s: %s"), path.c_str(), std::strerror(errno));
    fresh += '\n';
    bool written = write(fd, fresh.data(), fresh.size()) == ssize_t(fresh.size());
    close(fd);
    if (!written) return strf(tr("cannot write the class key %s"), path.c_str());
    fresh.pop_back();
    key = fresh;
    return {};
}

}  // namespace

std::string class_key(bool create, std::string& key) {
    const std::string path = class_key_path();
    if (path.empty()) return tr("no place for the class key: set PUPITRE_CLASS_KEY or HOME");
    return key_file(path, create, key);
}

std::string teacher_key_path() {
    if (const char* k = std::getenv("PUPITRE_TEACHER_KEY"); k && *k) return k;
    if (const char* x = std::getenv("XDG_CONFIG_HOME"); x && *x == '/')
        return std::string(x) + "/pupitre/teacher.key";
    if (const char* h = std::getenv("HOME"); h && *h)
        return std::string(h) + "/.config/pupitre/teacher.key";
    return {};
}

namespace {
constexpr std::string_view kTeacherIdSetting = "class.teacher_key_id";
std::string teacher_id(const std::string& key) {
    return sha256_hex("pupitre teacher key id\n" + key).substr(0, 16);
}
}  // namespace

std::string init_teacher_key(store::Store& st) {
    const std::string path = teacher_key_path();
    if (path.empty()) return tr("no place for the teacher's key: set PUPITRE_TEACHER_KEY or HOME");
    std::string key;
    if (std::string why = key_file(path, true, key); !why.empty()) return why;
    if (store::StoreError e = st.set_setting(kTeacherIdSetting, teacher_id(key))) return e.message;
    return {};
}

std::string teacher_allowed(store::Store& st) {
    auto id = st.setting(kTeacherIdSetting);
    if (id.error) return id.error.message;
    if (!id.value || id.value->empty()) return {};  // no teacher's key: the class key decides
    std::string key;
    const std::string path = teacher_key_path();
    if (path.empty() || !key_file(path, false, key).empty() || teacher_id(key) != *id.value)
        return strf(tr("exercise truth needs this store's teacher's key (%s, or "
                       "PUPITRE_TEACHER_KEY): pupitre class init made it"),
                    path.c_str());
    return {};
}

namespace {
constexpr std::string_view kKeyIdSetting = "class.key_id";
std::string key_id(const std::string& key) {
    return sha256_hex("pupitre class key id\n" + key).substr(0, 16);
}
}  // namespace

std::string store_class_key(store::Store& st, bool create, std::string& key) {
    auto id = st.setting(kKeyIdSetting);
    if (id.error) return id.error.message;
    if (std::string why = class_key(create && !id.value, key); !why.empty()) return why;
    if (!id.value) {
        if (store::StoreError e = st.set_setting(kKeyIdSetting, key_id(key))) return e.message;
        return {};
    }
    if (*id.value != key_id(key))
        return strf(tr("the class key %s is not the key of this store's class: set "
                       "PUPITRE_CLASS_KEY to the teacher's key file"),
                    class_key_path().c_str());
    return {};
}

std::string truth_allowed(store::Store& st, const training::Exercise& e, const std::string& student,
                          unsigned caller) {
    auto open = st.open_attempt(e.name, student);
    if (open.error) return open.error.message;
    if (!open.value) return {};
    struct stat sb;
    const std::string path = class_key_path();
    if (stat(path.c_str(), &sb) == 0 && sb.st_uid == caller) return {};
    return strf(tr("%s's attempt at %s is in progress: its truth is shown to the owner of the "
                   "class key %s, or once it is submitted"),
                student.c_str(), e.name.c_str(), path.c_str());
}

bool exercise_is_file(const std::string& name) {
    return name.find('/') != std::string::npos ||
           (name.size() > 9 && name.substr(name.size() - 9) == ".exercise");
}

std::string find_exercise(store::Store* st, const std::string& name, training::Exercise& e) {
    std::string text;
    const bool file = exercise_is_file(name);
    if (file) {
        bool ok = false;
        text = read_file(name, ok);
        if (!ok) return strf(tr("cannot read %s"), name.c_str());
    } else if (auto r = st ? st->exercise(name) : store::Result<std::optional<std::string>>{};
               r.value) {
        text = *r.value;
    } else if (training::builtin_exercise(name, e)) {
        return {};
    } else {
        return strf(tr("no exercise named %s (pupitre exercise list)"), name.c_str());
    }
    if (std::string why = training::parse_exercise(text, e); !why.empty())
        return strf(tr("%s: %s"), name.c_str(), why.c_str());
    return {};
}

std::string student_name(const std::string& asked) {
    return asked.empty() ? store::os_user() : asked;
}

std::string scramble(const std::string& text, uint64_t seed) {
    return "scrambled:" + to_hex(keystream_xor(text, seed));
}

std::string unscramble(const std::string& text, uint64_t seed) {
    if (text.rfind("scrambled:", 0) != 0) return {};
    std::string raw;
    for (size_t i = 10; i + 1 < text.size(); i += 2)
        raw += char(std::stoi(text.substr(i, 2), nullptr, 16));
    return keystream_xor(raw, seed);
}

training::Context record_context(const std::string& text) {
    training::Context c;
    std::vector<record::Action> actions;
    record::parse(text, actions);  // a line it cannot read ends it: what came before counts
    for (const record::Action& a : actions) {
        if (a.verb == record::Verb::dia) c.diameters.push_back(a.value);
        if (a.verb == record::Verb::shim) c.shims.push_back(a.value);
    }
    return c;
}

std::string sign_attempt(const store::Attempt& a, const std::string& key) {
    std::string fields = strf("%lld|%s|%s|%s|%lld|%lld|%s|%d|%.3f|%d|%d|", (long long)a.id,
                              a.exercise.c_str(), a.exercise_sha.c_str(), a.student.c_str(),
                              (long long)a.started_ms, (long long)a.submitted_ms, a.seed.c_str(),
                              a.score, a.seconds, a.crashes, a.scrapped ? 1 : 0);
    fields += a.mistakes + "|" + a.found + "|" + a.report;
    if (!a.record.empty()) fields += "|" + a.record;
    return hmac_sha256_hex(key, fields);
}

}  // namespace pupitre::console
