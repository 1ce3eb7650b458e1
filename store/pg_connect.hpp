// Inside the PostgreSQL backend: connecting to a class server, as people see
// it. The connection's short name (host/database), and libpq's messages made
// one line a teacher or a student can act on. store/postgres.cpp opens the
// store and hands these what libpq says. No libpq here. Not for use outside
// store/.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <string>

#include "store/store.hpp"

namespace pupitre::store::pg {

// libpq's message (several lines, a newline at the end) as one line.
std::string one_line(const char* msg);

// host/database as the connection found them (PGHOST and service files
// applied); a unix socket's directory is this machine.
std::string short_name(const char* host, const char* dbname);

// A failed connection's error (libpq's `message`; its user and database,
// null when unknown) as one line: authentication, a missing database, a
// server that does not answer, or else libpq's own words.
StoreError connect_error(const std::string& name, const char* message, const char* user,
                         const char* dbname);

}  // namespace pupitre::store::pg
