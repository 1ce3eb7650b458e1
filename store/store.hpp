// The program store (pupitre(1), PROGRAM STORE): the part programs with every
// revision, the tool correctors and origins of each machine with an audit of
// their changes, the machine profiles, settings, the IMD history, the
// workshops, exercises and attempts. One SQLite file (the default), or a
// database on a PostgreSQL server that a class shares (store/backend.hpp).
// Only store/ includes sqlite3.h or libpq-fe.h; this header is what the rest
// of pupitre sees.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace pupitre::store {

namespace db {
class Backend;
struct Meta;
}  // namespace db
namespace sql {
class Use;
}

inline constexpr uint32_t kApplicationId = 0x4E554D31;  // "NUM1" in PRAGMA application_id
inline constexpr int kSchemaVersion = 4;                // PRAGMA user_version we write
// A server's schema is one step ahead: its list's packed column (schema_pg.hpp).
inline constexpr int kServerSchemaVersion = 5;

// What went wrong, as the exit code the command line gives (sysexits).
enum class Fault {
    none,
    cannot_create,  // 73: the store or its directory cannot be created or written
    io,             // 74: I/O error, disk full, locked longer than the busy timeout
    bad_data,   // 65: not a database, not ours, newer schema, truncated or corrupt; a refused text
    not_found,  // 66: no such program or revision
};
int exit_code(Fault f);

// Errors are values (ARCHITECTURE.md, Conventions). The message names the file and says what to do.
struct StoreError {
    Fault fault = Fault::none;
    std::string message;
    // A serialization failure or a deadlock on a server: the transaction may
    // be run again (Store::in_write does, a bounded number of times).
    bool retry = false;
    // The server's connection is lost (stopped, restarted, out of reach):
    // nothing was written, and the same call may succeed once it answers.
    bool gone = false;
    explicit operator bool() const { return fault != Fault::none; }
};

template <class T>
struct Result {
    T value{};
    StoreError error;
    bool ok() const { return !error; }
};

struct Options {
    bool create = true;           // create (and seed) the file when it does not exist
    bool seed = true;             // seed machine profiles and demo programs at creation
    bool create_parents = false;  // mkdir -p the directory (the default store only)
    int busy_timeout_ms = 3000;   // how long to wait for another writer
    long max_page_count = 0;      // > 0: cap the file at this many pages (tests: disk full)
    std::string user;             // who is written in revisions and audit rows; "" = the OS user
    // The console: a server's connection that was lost is made again a step
    // at a time, from later calls, so no call waits on the network for it
    // (calls meanwhile fail as "the server is gone"). Batch commands wait.
    bool live = false;
};

// The default store: $XDG_DATA_HOME/pupitre/pupitre.db, else ~/.local/share/pupitre/pupitre.db.
// Empty when neither XDG_DATA_HOME nor HOME (nor the password entry) gives a directory.
std::string default_path();
// The OS user: $USER, else the password entry of the real uid, else "uid N".
std::string os_user();

// ---- programs ----

// based_on values for save(): the revision the caller loaded, or one of these.
inline constexpr int kNew = 0;    // the caller saw no program under this number
inline constexpr int kHead = -1;  // whatever is current (import, restore): never a conflict

struct ProgramInfo {
    int number = 0;
    int index = -1;     // %number.index, -1 when none
    std::string title;  // the header comment
    int revision = 0;   // the current revision
    int conflict = 0;   // a revision kept aside by a conflicting save, 0 when none
    bool deleted = false;
    int64_t size = 0;  // bytes
    int64_t lines = 0;
    int64_t modified_ms = 0;  // Unix time in milliseconds
    std::string modified_by;
};

struct Program {
    ProgramInfo info;
    int revision = 0;  // the revision whose text this is
    std::string text;  // exactly as imported or saved
};

enum class RevisionKind { import, save, restore, remove, seed };
std::string_view kind_name(RevisionKind k);

struct RevisionInfo {
    int revision = 0;
    RevisionKind kind = RevisionKind::save;
    int based_on = 0;       // the revision the writer had loaded (0: none)
    bool conflict = false;  // kept aside: it was based on an older revision than the current one
    int64_t at_ms = 0;
    std::string who;
    std::string source;  // "import part.iso", "restore r3", "page EDIT"…
    int64_t size = 0;    // bytes (0 for a deletion)
    int64_t lines = 0;
};

enum class SaveStatus { created, saved, unchanged, conflict };

struct SaveResult {
    int number = 0;
    SaveStatus status = SaveStatus::saved;
    int revision = 0;        // the revision written (for unchanged: the current one)
    int current = 0;         // the current revision afterwards
    std::string current_by;  // who wrote the current revision (to name in a conflict)
    bool deleted = false;    // the program is deleted afterwards (a conflict with a deletion)
};

// One program ready to be stored: its number and its exact text.
struct Piece {
    int number = 0;
    std::string text;
    std::string source;  // "import part.iso", shown in the history
};

// ---- machine values: correctors and origins ----

// Values are named as --set names them (pupitre(1), OPTIONS): "D3.X", "D12.DL", "PREF.Z",
// "DEC1.X", "DEC3.B", and held in the internal units of the E parameters: µm
// (lathe X gauges and origins as radii, DX a diameter), 0.0001° for rotary axes,
// the orientation code for C.
struct Change {
    std::string name;
    std::optional<int64_t> old_value;  // nullopt: not stored before (profile default)
    int64_t new_value = 0;
};

struct AuditRow {
    int64_t id = 0;
    int64_t at_ms = 0;
    std::string who;
    std::string machine;
    std::string name;
    std::optional<int64_t> old_value;
    std::optional<int64_t> new_value;
    std::string source;  // "page CORR", "program %555 (tools.iso)"
};

struct ImdEntry {
    int64_t id = 0;
    int64_t at_ms = 0;
    std::string who;
    std::string machine;
    std::string block;
};

// An exercise's attempt (pupitre-exercise(5)). `submitted_ms` 0: in progress.
struct Attempt {
    int64_t id = 0;
    std::string exercise, exercise_sha, student, machine;
    int64_t started_ms = 0, submitted_ms = 0;
    std::string seed;
    int score = 0;
    double seconds = 0;
    int crashes = 0;
    bool scrapped = false;
    std::string mistakes, found, report, signature;
    // What the operator did, the teacher's side replays it to grade
    // (console/record.hpp); before version 1, the readings and shims alone.
    std::string record;
};

// What `store copy` did: rows copied per table, and whether both sides agree.
struct CopyReport {
    struct Table {
        std::string name;
        int64_t rows = 0;
        std::string checksum;  // SHA-256 of the table's rows in key order, both sides
    };
    std::vector<Table> tables;
};

// ---- the class on a server (pupitre-exercise(5), THE CLASS ON A SERVER) ----

// A login of the class: its name, its class (a group role) and, once, when
// `class add-student` made it, its initial password.
struct Login {
    std::string name, group, password;
};
// A name pupitre makes a login or a class of: lowercase letters, digits,
// _ . -, beginning with a letter, not pg_… or pupitre_…, at most 63 bytes.
bool login_name_ok(std::string_view name);
struct NamedText {
    std::string name, text;
};
// A student as the teacher's watch shows them (Store::class_status): their
// last attempt, its counts, their last action on a machine, whether a
// session of their login is connected now, and the server's clock.
struct StudentStatus {
    std::string login, group;
    int64_t attempt = 0;  // the last one's id (0: none yet)
    std::string exercise;
    int64_t started_ms = 0, submitted_ms = 0;  // submitted 0: in progress
    bool graded = false;
    int score = -1;
    int attempts = 0, crashes = 0, scrapped = 0;  // over all their attempts
    int64_t last_ms = 0;                          // their last value set (0: none)
    std::string last_name;                        // its name ("PREF.X")
    std::optional<int64_t> last_value;            // its value in the store's units
    bool connected = false;
    int64_t now_ms = 0;  // the server's clock
};

// Inside the store, whose files define them: a program's row as a write
// reads it (store/programs.cpp), the columns a corrector's or origin's name
// is stored in (store/values.cpp), a program text's header (store/text.hpp).
struct ProgramRow;
struct StoredName;
struct Header;

// One connection to a store. Not shared between threads: a thread or a
// process opens its own. SQLite serialises the writers (WAL, BEGIN
// IMMEDIATE); PostgreSQL runs each write SERIALIZABLE and the store runs it
// again when the server refuses it for a concurrent one.
class Store {
  public:
    // Opens (and on first use creates and seeds) the store at `target`: a file
    // path, or a PostgreSQL connection string (postgresql://… or key=value;
    // libpq's PG* variables, ~/.pgpass and service files apply). Never
    // modifies a file or database that is not a pupitre store, a store of a
    // newer schema, or a damaged one: those give bad_data.
    static Result<std::unique_ptr<Store>> open(const std::string& target, const Options& o = {});
    ~Store();
    Store(const Store&) = delete;
    Store& operator=(const Store&) = delete;

    // The store's name for people: its file, or its server URI without password.
    const std::string& path() const { return path_; }
    // Its name where a line is short (the console's message line): its
    // file, or a server's host and database, "host/database".
    const std::string& short_name() const { return short_name_; }
    // What it was opened with (a file path or a connection string), to open it again.
    const std::string& target() const { return target_; }
    // Where this PC keeps what belongs beside the store on local disk (the
    // editor's recovery journal): the file itself for SQLite; for a server,
    // a name under the default store's directory.
    std::string local_path() const;
    // "sqlite" or "postgresql".
    std::string_view engine() const;
    // How many times a write was run again after a serialization failure.
    int64_t retried() const { return retried_; }
    const std::string& user() const { return user_; }
    // Where the machine `name` is kept. On a class's server (class init)
    // each login has machines of its own, "LOGIN/NAME" ("alice/lathe"): 30
    // students at 30 consoles each set their own lathe. A name with a '/' is
    // taken as it is (a teacher looking at a student's); on a file or a
    // server with no class, the name itself, shared by every login.
    std::string machine_row(std::string_view name) const;
    // A stored machine's name as this login calls it: its own without the
    // "LOGIN/" (the reverse of machine_row), another's whole.
    std::string machine_shown(std::string_view row) const;
    bool created() const { return created_; }  // this open created the file

    // Programs. Each call is one transaction.
    Result<std::vector<ProgramInfo>> list();
    // The current text (revision 0) or a given revision of a program.
    Result<Program> read(int number, int revision = 0);
    // Saves `text` as program `number`. A text that differs from the current one
    // and is based on an older revision than the current one is a conflict: it
    // is kept as a revision flagged "conflict", the current revision stays, and
    // the program is marked until a save based on the current revision or a
    // restore resolves it. A text equal to the current one is "unchanged".
    Result<SaveResult> save(int number, std::string_view text, int based_on,
                            std::string_view source);
    // Saves several programs in one transaction (import): all or none.
    Result<std::vector<SaveResult>> save_all(const std::vector<Piece>& pieces);
    // Deletes a program: a deletion revision; the history stays and restore brings it back.
    Result<SaveResult> remove(int number, int based_on = kHead, std::string_view source = "rm");
    Result<std::vector<RevisionInfo>> history(int number);
    // Calls f(number, text) for the current text of every program, in number
    // order, from one snapshot (program memory for a run).
    StoreError each_program(const std::function<void(int, std::string_view)>& f);
    // Makes the text of an earlier revision current again, as a new revision.
    Result<SaveResult> restore(int number, int revision, std::string_view source = "");

    // Machine profiles (the .machine text).
    Result<std::vector<std::string>> machines();
    Result<std::string> machine_profile(std::string_view name);
    StoreError put_machine(std::string_view name, std::string_view profile);

    // Correctors and origins of a machine (only the stored ones).
    Result<std::map<std::string, int64_t>> values(std::string_view machine);
    // Writes values in one transaction with one audit row per real change;
    // returns the changes made (unchanged values are skipped). The machine is
    // added with `profile` when the store does not know it yet.
    Result<std::vector<Change>> set_values(std::string_view machine,
                                           const std::vector<std::pair<std::string, int64_t>>& v,
                                           std::string_view source, std::string_view profile = "");
    Result<std::vector<AuditRow>> audit(std::string_view machine = "", int limit = 0);

    // Settings (key/value text) and the IMD history.
    Result<std::optional<std::string>> setting(std::string_view key);
    // The workshop of a machine (pupitre-setup(5)): the setup's text and the
    // part's text; none when the machine has no workshop. An empty setup
    // removes it.
    struct Workshop {
        std::string setup, part;
    };
    Result<std::optional<Workshop>> workshop(std::string_view machine);
    StoreError put_workshop(std::string_view machine, std::string_view setup,
                            std::string_view part);
    StoreError set_setting(std::string_view key, std::string_view value);
    StoreError add_imd(std::string_view machine, std::string_view block);
    Result<std::vector<ImdEntry>> imd_history(std::string_view machine, int limit = 100);

    // Training (store/training.cpp): the class's exercises, the attempts.
    // An exercise's text; the text it replaces is kept (exercise_text) for
    // the attempts made on it.
    StoreError put_exercise(std::string_view name, std::string_view text);
    // The text of `name` whose SHA-256 is `sha`: the current one or one it
    // replaced; nullopt when the store has neither.
    Result<std::optional<std::string>> exercise_text(std::string_view name, std::string_view sha);
    Result<std::optional<std::string>> exercise(std::string_view name);
    Result<std::vector<std::string>> exercises();
    // The attempt of `student` at `exercise` still in progress, if any.
    Result<std::optional<Attempt>> open_attempt(std::string_view exercise,
                                                std::string_view student);
    // Starts an attempt (its id filled in, its machine named after it).
    StoreError start_attempt(Attempt& a);
    StoreError add_crash(int64_t id);
    // The record of an attempt in progress as it grows, so that a console
    // that stops and starts again takes it up (on a class's server through
    // the server's function). Nothing when it was submitted meanwhile.
    StoreError keep_record(int64_t id, std::string_view record);
    // Writes the grade of an attempt in progress; not_found when it was
    // submitted already.
    StoreError submit_attempt(const Attempt& a);
    // Every attempt (of one exercise when `exercise` is given), oldest first.
    Result<std::vector<Attempt>> attempts(std::string_view exercise = "");

    // The class (store/class.cpp; PostgreSQL only). Whether `class init` set
    // it up in this store: attempts are then opened, crashed and submitted
    // through the server's functions, their seed drawn there.
    Result<bool> class_server();
    // Sets the class up (roles, grants, policies, key, functions: once) and
    // the class `group`; the shipped `exercises` are added where missing.
    StoreError class_init(std::string_view group, const std::vector<NamedText>& exercises);
    // Logins for `names` in `group`, each with a random password, returned once.
    Result<std::vector<Login>> add_students(std::string_view group,
                                            const std::vector<std::string>& names);
    Result<std::vector<Login>> students(std::string_view group = "");  // "": every class
    Result<std::string> class_signing_key();                           // a teacher's login reads it
    // Every student of `group` ("": every class) with their status: one query.
    Result<std::vector<StudentStatus>> class_status(std::string_view group = "");
    // This login's attempt at `exercise`: its open one, else a new one with
    // a seed the server draws; the machine `machine` (made LOGIN/…) is its.
    Result<Attempt> open_class_attempt(std::string_view exercise, std::string_view machine);
    // :submit: the provisional result and the record, at the server's time.
    StoreError submit_class_attempt(const Attempt& a);
    // The teacher's grade, signed, of a submitted attempt not yet graded.
    StoreError grade_attempt(const Attempt& a);

    // A number that changes when another connection (another console)
    // commits, not on this one's own writes. Polled to follow other consoles.
    Result<int64_t> data_version();

    // "ok" or the problems found (SQLite's integrity and foreign key checks;
    // on a server, the store's own cross-table checks).
    Result<std::string> integrity_check();

    // Copies this whole store into `target`, which must hold no programs,
    // exercises or attempts yet (store/copy.cpp): programs with every
    // revision, machines with their values and audit, settings, IMD history,
    // workshops, exercises and attempts, in one transaction on the target;
    // then compares each table's row count and checksum on both sides.
    Result<CopyReport> copy_to(Store& target);

  private:
    Store();
    StoreError fail(int rc, std::string_view what);
    // A statement that changes one row and returns it (RETURNING, or a
    // function's answer): no row, or a NULL, is `gone` (Fault::not_found);
    // a failure says `what` could not be done. `u` is bound, without error.
    StoreError one_row(sql::Use& u, const char* gone, const char* what);
    StoreError exec(const char* sql);
    sql::Use use(const char* sql);
    sql::Use use_many(const char* sql);  // Backend::prepare_many
    StoreError begin_write();
    StoreError begin_read();
    StoreError commit();
    void rollback();
    template <class F>
    auto in_write(F&& body) -> decltype(body());
    static Result<std::unique_ptr<Store>> open_sqlite(const std::string& path, const Options& o);
    static Result<std::unique_ptr<Store>> open_postgres(const std::string& target,
                                                        const Options& o);
    StoreError create_file();
    // `known`: the store's meta as just read (a server's open), not read again.
    StoreError validate_and_migrate(bool& fresh, const db::Meta* known = nullptr);
    StoreError seed();
    StoreError read_row(int number, ProgramRow& row, const std::string& what);
    StoreError insert_revision(int number, int rev, RevisionKind kind, int based_on, bool conflict,
                               const std::string* text, const std::string& source,
                               const std::string& what, int unless = 0, bool* written = nullptr);
    StoreError has_revision(int number, int rev, const std::string& what);
    StoreError same_text(int number, int rev, std::string_view text, bool& same,
                         const std::string& what);
    template <class... T>
    StoreError update_program(const char* sql, const std::string& what, int number,
                              const T&... more);
    Result<SaveResult> save_one(const Piece& p, int based_on, RevisionKind kind);
    struct ImportPlan;
    template <class F>
    StoreError for_numbers(const char* head, const std::vector<int>& numbers,
                           const std::string& what, F&& f);
    StoreError read_import(const std::vector<Piece>& pieces, ImportPlan& plan,
                           const std::string& what);
    Result<std::vector<SaveResult>> plan_import(const std::vector<Piece>& pieces,
                                                const std::vector<Header>& headers,
                                                ImportPlan& plan, const std::string& what);
    StoreError write_import(const ImportPlan& plan);
    Result<std::string> revision_text(int number, int revision, const std::string& what);
    Result<CopyReport::Table> table_sum(const char* name, const char* select, const char* kinds);

    Result<std::vector<Change>> write_values(std::string_view machine,
                                             const std::vector<std::pair<std::string, int64_t>>& v,
                                             const std::vector<StoredName>& names,
                                             std::string_view source, std::string_view profile,
                                             const std::string& what);
    int64_t now_ms() const;
    int class_state_ = -1;  // class_server(): -1 not asked yet, 0 no, 1 yes

    std::unique_ptr<db::Backend> db_;
    std::string path_;
    std::string short_name_;
    std::string target_;
    std::string user_;
    bool created_ = false;
    int64_t retried_ = 0;
    Options opt_;
};

}  // namespace pupitre::store
