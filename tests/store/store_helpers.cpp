// Store test helpers on both engines: a place for stores (a directory, or a
// schema on the test PostgreSQL server) and the fixture that runs a case on each.
// SPDX-License-Identifier: GPL-3.0-or-later
#include "store_helpers.hpp"

#include <libpq-fe.h>

#include <atomic>

namespace pupitre::test {

namespace {
std::atomic<int> g_schema_counter{0};
}

std::string pg_admin(const std::string& sql) {
    const char* conninfo = std::getenv("PUPITRE_TEST_PG");
    if (!conninfo) return "PUPITRE_TEST_PG is not set";
    PGconn* c = PQconnectdb(conninfo);
    std::string out;
    if (PQstatus(c) != CONNECTION_OK) {
        out = PQerrorMessage(c);
    } else {
        PQclear(PQexec(c, "SET client_min_messages = warning"));
        PGresult* r = PQexec(c, sql.c_str());
        ExecStatusType st = PQresultStatus(r);
        if (st != PGRES_COMMAND_OK && st != PGRES_TUPLES_OK) out = PQresultErrorMessage(r);
        PQclear(r);
    }
    PQfinish(c);
    return out;
}

std::string Place::operator/(const std::string& name) {
    if (engine_ == "sqlite") return dir_ / name;
    for (const auto& [n, target] : made_)
        if (n == name) return target;
    std::string schema =
        "t" + std::to_string(::getpid()) + "_" + std::to_string(g_schema_counter++);
    std::string err = pg_admin("CREATE SCHEMA " + schema);
    EXPECT_EQ(err, "") << "cannot make a schema on the test server";
    schemas_.push_back(schema);
    std::string target =
        std::string(std::getenv("PUPITRE_TEST_PG")) + " options='-csearch_path=" + schema + "'";
    made_.emplace_back(name, target);
    return target;
}

Place::~Place() {
    for (const std::string& s : schemas_) pg_admin("DROP SCHEMA " + s + " CASCADE");
}

void OnBothEngines::SetUp() {
    if (GetParam() != "postgresql" || std::getenv("PUPITRE_TEST_PG")) return;
    const char* ci = std::getenv("CI");
    if (ci && std::string(ci) == "true")
        FAIL() << "CI=true and no PostgreSQL test server: scripts/test starts one";
    GTEST_SKIP() << "no PostgreSQL test server (scripts/test starts one)";
}

std::string engine_name(const ::testing::TestParamInfo<std::string>& p) {
    return p.param == "sqlite" ? "SQLite" : "PostgreSQL";
}

}  // namespace pupitre::test
