// Connecting to a class server, as people see it (store/pg_connect.hpp).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "store/pg_connect.hpp"

#include <cstring>

#include "core/i18n.hpp"

namespace pupitre::store {

namespace pg {

// libpq's messages end in a newline and may hold several lines; a store
// message is one line.
std::string one_line(const char* msg) {
    std::string s = msg ? msg : "";
    while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
    // "connection to server at "h" (127.0.0.1), port 5432 failed: FATAL:  x" -> "x"
    for (const char* cut : {"failed: ", "FATAL:  ", "ERROR:  "}) {
        size_t at = s.rfind(cut);
        if (at != std::string::npos) s = s.substr(at + std::strlen(cut));
    }
    size_t nl = s.find('\n');
    if (nl != std::string::npos) s = s.substr(0, nl);
    return s;
}

namespace {

bool contains(const std::string& s, const char* what) {
    return s.find(what) != std::string::npos;
}

}  // namespace

std::string short_name(const char* host, const char* dbname) {
    const std::string h = host ? host : "";
    return (h.empty() || h[0] == '/' ? std::string("localhost") : h) + "/" + (dbname ? dbname : "");
}

StoreError connect_error(const std::string& name, const char* message, const char* user,
                         const char* dbname) {
    std::string m = one_line(message);
    const bool no_role = contains(m, "role \"") && contains(m, "does not exist");
    if (contains(m, "password authentication failed") || contains(m, "no password supplied") ||
        contains(m, "pg_hba.conf") || contains(m, "authentication failed") || no_role)
        return {Fault::cannot_create,
                strf(tr("%s: authentication failed for %s (pupitre never asks for a password: "
                        "use ~/.pgpass, PGPASSFILE or PGSERVICE)"),
                     name.c_str(), user ? user : "?")};
    if (contains(m, "does not exist") && contains(m, "database \""))
        return {Fault::not_found,
                strf(tr("%s: the database %s does not exist (a teacher creates it: createdb)"),
                     name.c_str(), dbname ? dbname : "?")};
    if (contains(m, "Connection refused") || contains(m, "timeout expired") ||
        contains(m, "could not translate host name") || contains(m, "No such file or directory") ||
        contains(m, "Network is unreachable") || contains(m, "No route to host"))
        return {Fault::io,
                strf(tr("%s: the server does not answer (%s)"), name.c_str(), m.c_str())};
    return {Fault::cannot_create, strf(tr("%s: cannot connect: %s"), name.c_str(), m.c_str())};
}

}  // namespace pg

}  // namespace pupitre::store
