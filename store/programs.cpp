// Programs in the store: save with conflict detection, import, delete, history,
// restore. Every revision is kept; the current one is programs.head.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <endian.h>

#include <algorithm>
#include <cstring>
#include <optional>

#include "core/i18n.hpp"
#include "store/sql.hpp"
#include "store/store.hpp"
#include "store/text.hpp"

namespace pupitre::store {

std::string_view kind_name(RevisionKind k) {
    switch (k) {
        case RevisionKind::import:
            return "import";
        case RevisionKind::save:
            return "save";
        case RevisionKind::restore:
            return "restore";
        case RevisionKind::remove:
            return "delete";
        case RevisionKind::seed:
            return "seed";
    }
    return "save";
}

namespace {

void bind_value(sql::Use& u, int i, int v) {
    u.bind(i, v);
}
void bind_value(sql::Use& u, int i, int64_t v) {
    u.bind(i, v);
}
void bind_value(sql::Use& u, int i, const std::string& v) {
    u.bind(i, v);
}
void bind_value(sql::Use& u, int i, const std::optional<int64_t>& v) {
    if (v)
        u.bind(i, *v);
    else
        u.null(i);
}

RevisionKind kind_of(std::string_view s) {
    if (s == "import") return RevisionKind::import;
    if (s == "restore") return RevisionKind::restore;
    if (s == "delete") return RevisionKind::remove;
    if (s == "seed") return RevisionKind::seed;
    return RevisionKind::save;
}

std::string pct(int n) {
    return "%" + std::to_string(n);
}

// A program is stored under its own number: not negative, and the same as the
// one its % line gives, if any. `h` receives the text's header.
StoreError check_number(const Piece& p, const std::string& path, Header& h) {
    if (p.number < 0)
        return {Fault::bad_data,
                strf(tr("%s: program number %d is negative"), path.c_str(), p.number)};
    if (StoreError e = parse_program(p.text, pct(p.number), h)) return e;
    if (h.number >= 0 && h.number != p.number)
        return {
            Fault::bad_data,
            strf(tr("%%%d: the text's %% line says %%%d; a program is stored under its own number"),
                 p.number, h.number)};
    return {};
}

constexpr const char* kSelectRow =
    "SELECT head, last_rev, conflict, deleted, size, modified_by FROM programs WHERE number = ?1";
constexpr const char* kSelectText = "SELECT text FROM revisions WHERE program = ?1 AND rev = ?2";
constexpr const char* kInsertRevision =
    "INSERT INTO revisions (program, rev, kind, based_on, conflict, text, size, lines, who, at_ms, "
    "source) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11)";
// The same, unless the text is that of revision ?12, compared where the
// texts are (a save on a server of the current text's size). No row: not
// written.
constexpr const char* kInsertIfChanged =
    "INSERT INTO revisions (program, rev, kind, based_on, conflict, text, size, lines, who, at_ms, "
    "source) SELECT ?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10, ?11 FROM revisions WHERE program = ?1 "
    "AND rev = ?12 AND (text IS NULL OR text <> ?6) RETURNING rev";
constexpr const char* kHasRevision = "SELECT 1 FROM revisions WHERE program = ?1 AND rev = ?2";
constexpr const char* kInsertProgram =
    "INSERT INTO programs (number, idx, title, head, last_rev, conflict, deleted, size, lines, "
    "modified_ms, modified_by) VALUES (?1, ?2, ?3, ?4, ?4, NULL, 0, ?5, ?6, ?7, ?8)";
constexpr const char* kUpdateHead =
    "UPDATE programs SET idx = ?2, title = ?3, head = ?4, last_rev = ?4, conflict = NULL, deleted "
    "= 0, "
    "size = ?5, lines = ?6, modified_ms = ?7, modified_by = ?8 WHERE number = ?1";
constexpr const char* kUpdateConflict =
    "UPDATE programs SET last_rev = ?2, conflict = ?2 WHERE number = ?1";
constexpr const char* kClearConflict = "UPDATE programs SET conflict = NULL WHERE number = ?1";
constexpr const char* kDelete =
    "UPDATE programs SET head = ?2, last_rev = ?2, conflict = NULL, deleted = 1, size = 0, lines = "
    "0, "
    "modified_ms = ?3, modified_by = ?4 WHERE number = ?1";
// A program's ProgramInfo. The list reads kListColumns, all but `deleted`
// (it lists the programs that are not): one value fewer for a server to send
// for each program.
constexpr const char* kInfoColumns =
    "number, idx, title, head, conflict, size, lines, modified_ms, modified_by, deleted";
constexpr const char* kListColumns =
    "number, idx, title, head, conflict, size, lines, modified_ms, modified_by";

// A row of kInfoColumns, or of kListColumns when `listed`, into `i` (a list
// fills its entries where they are).
void read_info(const sql::Use& u, ProgramInfo& i, bool listed) {
    i.number = u.i32(0);
    i.index = u.is_null(1) ? -1 : u.i32(1);
    i.title = u.view(2);
    i.revision = u.i32(3);
    i.conflict = u.is_null(4) ? 0 : u.i32(4);
    i.size = u.i64(5);
    i.lines = u.i64(6);
    i.modified_ms = u.i64(7);
    i.modified_by = u.view(8);
    i.deleted = !listed && u.i32(9) != 0;
}

// A row of a server's packed list (Backend::packed_list): the integers from
// the listing column, seven big-endian 8-byte values, then title and author.
// False when the value is not that long (a damaged row, refused).
bool read_packed(const sql::Use& u, ProgramInfo& i) {
    const std::string_view p = u.view(0);
    if (p.size() != 7 * 8) return false;
    int64_t v[7];
    for (size_t k = 0; k < 7; ++k) {
        uint64_t x;
        std::memcpy(&x, p.data() + k * 8, 8);
        v[k] = int64_t(be64toh(x));
    }
    i.number = int(v[0]);
    i.index = int(v[1]);
    i.revision = int(v[2]);
    i.conflict = int(v[3]);
    i.size = v[4];
    i.lines = v[5];
    i.modified_ms = v[6];
    i.title = u.view(1);
    i.modified_by = u.view(2);
    return true;
}

ProgramInfo info_of(const sql::Use& u) {
    ProgramInfo i;
    read_info(u, i, false);
    return i;
}

// Sorts a list by number: the rows that follow in order stay, the others
// (rows a save moved in the table) are sorted and merged in, each moved once.
void in_number_order(std::vector<ProgramInfo>& v) {
    std::vector<size_t> in_order, others;
    for (size_t i = 0; i < v.size(); ++i) {
        if (in_order.empty() || v[i].number > v[in_order.back()].number)
            in_order.push_back(i);
        else
            others.push_back(i);
    }
    if (others.empty()) return;
    auto by_number = [&](size_t a, size_t b) { return v[a].number < v[b].number; };
    std::sort(others.begin(), others.end(), by_number);
    std::vector<size_t> order(v.size());
    std::merge(in_order.begin(), in_order.end(), others.begin(), others.end(), order.begin(),
               by_number);
    std::vector<ProgramInfo> sorted;
    sorted.reserve(v.size());
    for (size_t i : order) sorted.push_back(std::move(v[i]));
    v = std::move(sorted);
}

}  // namespace

// The programs row of one number, inside a transaction.
struct ProgramRow {
    bool found = false;
    int head = 0, last = 0, conflict = 0;
    bool deleted = false;
    int64_t size = 0;
    std::string modified_by;
};

namespace {

// kSelectRow's columns, from column `c` on.
void row_of(const sql::Use& u, int c, ProgramRow& row) {
    row.found = true;
    row.head = u.i32(c);
    row.last = u.i32(c + 1);
    row.conflict = u.is_null(c + 2) ? 0 : u.i32(c + 2);
    row.deleted = u.i32(c + 3) != 0;
    row.size = u.i64(c + 4);
    row.modified_by = u.str(c + 5);
}

}  // namespace

StoreError Store::read_row(int number, ProgramRow& row, const std::string& what) {
    row = ProgramRow{};
    StoreError e;
    sql::Use u = use(kSelectRow);
    e = u.error;
    if (e) return e;
    int rc = u.bind(1, number).step();
    if (rc == db::kDone) return {};
    if (rc != db::kRow) return fail(rc, what);
    row_of(u, 0, row);
    return {};
}

// Appends revision `rev` of a program; a null text is a deletion. With
// `unless` > 0, only when the text differs from revision `unless`'s:
// `written` says whether it did.
StoreError Store::insert_revision(int number, int rev, RevisionKind kind, int based_on,
                                  bool conflict, const std::string* text, const std::string& source,
                                  const std::string& what, int unless, bool* written) {
    StoreError e;
    sql::Use u = use(unless > 0 ? kInsertIfChanged : kInsertRevision);
    e = u.error;
    if (e) return e;
    if (unless > 0) u.bind(12, unless);
    u.bind(1, number)
        .bind(2, rev)
        .bind(3, kind_name(kind))
        .bind(4, based_on)
        .bind(5, conflict ? 1 : 0);
    if (text)
        u.blob(6, *text).bind(7, int64_t(text->size())).bind(8, count_lines(*text));
    else
        u.null(6).bind(7, int64_t(0)).bind(8, int64_t(0));
    u.bind(9, user_).bind(10, now_ms()).bind(11, source);
    int rc = u.step();
    if (written) *written = rc == db::kRow || unless <= 0;
    return rc == db::kDone || (rc == db::kRow && unless > 0) ? StoreError{} : fail(rc, what);
}

// Revision `rev` of a program, which its programs row names, is there (else
// the store is damaged); same_text also says whether its text is `text`.
StoreError Store::has_revision(int number, int rev, const std::string& what) {
    StoreError e;
    sql::Use u = use(kHasRevision);
    if ((e = u.error)) return e;
    int rc = u.bind(1, number).bind(2, rev).step();
    return rc == db::kRow ? StoreError{} : fail(rc == db::kDone ? db::kCorrupt : rc, what);
}

StoreError Store::same_text(int number, int rev, std::string_view text, bool& same,
                            const std::string& what) {
    StoreError e;
    sql::Use u = use(kSelectText);
    if ((e = u.error)) return e;
    int rc = u.bind(1, number).bind(2, rev).step();
    if (rc != db::kRow) return fail(rc == db::kDone ? db::kCorrupt : rc, what);
    same = u.view(0) == text;
    return {};
}

// Runs a one-row statement on the programs table: bindings ?1 number, then `more`.
template <class... T>
StoreError Store::update_program(const char* sql, const std::string& what, int number,
                                 const T&... more) {
    StoreError e;
    sql::Use u = use(sql);
    e = u.error;
    if (e) return e;
    u.bind(1, number);
    int i = 2;
    (bind_value(u, i++, more), ...);
    int rc = u.step();
    return rc == db::kDone ? StoreError{} : fail(rc, what);
}

// Inside a write transaction: one program saved (see store.hpp for the rules).
Result<SaveResult> Store::save_one(const Piece& p, int based_on, RevisionKind kind) {
    Result<SaveResult> r;
    SaveResult& out = r.value;
    out.number = p.number;
    Header h;
    if ((r.error = check_number(p, path_, h))) return r;
    const std::string what = strf(tr("cannot save %%%d"), p.number);
    ProgramRow row;
    if ((r.error = read_row(p.number, row, what))) return r;
    const bool on_head = based_on == kHead || based_on == row.head;
    const bool clean = !row.found || on_head || (row.deleted && based_on == kNew);
    const int rev = row.found ? row.last + 1 : 1;
    const int base = based_on == kHead ? row.head : std::max(based_on, 0);
    // A text of the current one's size may be that text, written only if
    // not. SQLite compares it here; a server as it writes the revision, so
    // that the text crosses the network once and the current one never.
    const bool maybe = row.found && !row.deleted && row.size == int64_t(p.text.size());
    const bool remote = db_->remote();
    bool same = false, written = false;
    if (maybe && !remote && (r.error = same_text(p.number, row.head, p.text, same, what))) return r;
    if (!same && (r.error = insert_revision(p.number, rev, kind, base, !clean, &p.text, p.source,
                                            what, maybe && remote ? row.head : 0, &written)))
        return r;
    if (!written) {
        if (!same && (r.error = has_revision(p.number, row.head, what))) return r;
        out.status = SaveStatus::unchanged;
        out.revision = out.current = row.head;
        out.current_by = row.modified_by;
        if (row.conflict && on_head) r.error = update_program(kClearConflict, what, p.number);
        return r;
    }
    out.revision = rev;
    if (!clean) {
        out.status = SaveStatus::conflict;
        out.current = row.head;
        out.current_by = row.modified_by;
        out.deleted = row.deleted;
        r.error = update_program(kUpdateConflict, what, p.number, rev);
        return r;
    }
    const std::optional<int64_t> index =
        h.index >= 0 ? std::optional<int64_t>(h.index) : std::nullopt;
    r.error =
        update_program(row.found ? kUpdateHead : kInsertProgram, what, p.number, index, h.title,
                       rev, int64_t(p.text.size()), count_lines(p.text), now_ms(), user_);
    out.status = (!row.found || row.deleted) ? SaveStatus::created : SaveStatus::saved;
    out.current = rev;
    out.current_by = user_;
    return r;
}

Result<SaveResult> Store::save(int number, std::string_view text, int based_on,
                               std::string_view source) {
    const Piece p{number, std::string(text), std::string(source)};
    return in_write([&] { return save_one(p, based_on, RevisionKind::save); });
}

// ---- import: many programs in a few statements ----
//
// save_one for each piece would be three or four statements a program, each a
// round trip to a server. An import reads the rows of all its numbers first
// (and the current texts it may find unchanged), decides each piece in order
// as save_one would with based_on kHead, then writes the revisions and the
// programs rows in bulk (Backend::insert_rows: a COPY on a server) and in
// multi-row statements (sql::repeated, sql::in_batches).

namespace {

// Numbers per read; the unused places of the last read stay NULL.
constexpr int kNumbersPerRead = 256;
constexpr const char* kRowsOf =
    "SELECT number, head, last_rev, conflict, deleted, size, modified_by FROM programs WHERE "
    "number IN (";
constexpr const char* kHeadTextsOf =
    "SELECT r.program, r.text FROM programs p JOIN revisions r ON r.program = p.number AND "
    "r.rev = p.head WHERE p.number IN (";
constexpr const char* kClearConflicts = "UPDATE programs SET conflict = NULL WHERE number IN (";
constexpr const char* kRevisionColumns =
    "program, rev, kind, based_on, conflict, text, size, lines, who, at_ms, source";
constexpr const char* kProgramColumns =
    "number, idx, title, head, last_rev, conflict, deleted, size, lines, modified_ms, modified_by";
constexpr const char* kUpsertPrograms =
    "INSERT INTO programs (number, idx, title, head, last_rev, conflict, deleted, size, lines, "
    "modified_ms, modified_by) VALUES ";
constexpr const char* kProgramRow = "(?1, ?2, ?3, ?4, ?4, NULL, 0, ?5, ?6, ?7, ?8)";
constexpr const char* kUpsertTail =
    " ON CONFLICT (number) DO UPDATE SET idx = excluded.idx, title = excluded.title, head = "
    "excluded.head, last_rev = excluded.last_rev, conflict = NULL, deleted = 0, size = "
    "excluded.size, lines = excluded.lines, modified_ms = excluded.modified_ms, modified_by = "
    "excluded.modified_by";

}  // namespace

// An import decided: each number's row as the pieces leave it, and what to write.
struct Store::ImportPlan {
    struct Now {
        ProgramRow row;
        std::string stored;                    // the current text as read
        std::optional<std::string_view> text;  // the current text, when known
        bool seen = false;
        bool in_table = false;  // a programs row before the import
    };
    struct Revision {
        const Piece* piece;
        int rev, base;
        int64_t lines, at_ms;
    };
    struct Head {
        std::optional<int64_t> index;
        std::string title;
        int rev;
        int64_t size, lines, at_ms;
    };
    std::map<int, Now> now;
    std::vector<Revision> revisions;
    std::map<int, Head> heads;  // the programs rows to write: each number's last
    std::vector<int> cleared;   // unchanged texts that settle a conflict
};

// Runs `head` (a statement ending in "IN (") over `numbers`,
// kNumbersPerRead at a time; f(u) for each row it gives.
template <class F>
StoreError Store::for_numbers(const char* head, const std::vector<int>& numbers,
                              const std::string& what, F&& f) {
    const char* sql = sql::repeated(head, "?1", 1, kNumbersPerRead, ")");
    for (size_t at = 0; at < numbers.size(); at += kNumbersPerRead) {
        StoreError e;
        sql::Use u = use(sql);
        if ((e = u.error)) return e;
        for (size_t i = at; i < std::min(numbers.size(), at + kNumbersPerRead); ++i)
            u.bind(int(i - at + 1), numbers[i]);
        int rc;
        while ((rc = u.step()) == db::kRow) f(u);
        if (rc != db::kDone) return fail(rc, what);
    }
    return {};
}

// The rows of every number the pieces name, and the current texts of those
// whose first piece has the current text's size (it may be unchanged).
StoreError Store::read_import(const std::vector<Piece>& pieces, ImportPlan& plan,
                              const std::string& what) {
    std::vector<int> numbers;
    for (const Piece& p : pieces)
        if (plan.now.try_emplace(p.number).second) numbers.push_back(p.number);
    if (StoreError e = for_numbers(kRowsOf, numbers, what, [&](const sql::Use& u) {
            ImportPlan::Now& n = plan.now[u.i32(0)];
            row_of(u, 1, n.row);
            n.in_table = true;
        }))
        return e;
    std::vector<int> maybe;
    for (const Piece& p : pieces) {
        ImportPlan::Now& n = plan.now[p.number];
        if (n.seen) continue;  // a later piece of a number meets the earlier one's text
        n.seen = true;
        if (n.row.found && !n.row.deleted && n.row.size == int64_t(p.text.size()))
            maybe.push_back(p.number);
    }
    return for_numbers(kHeadTextsOf, maybe, what, [&](const sql::Use& u) {
        ImportPlan::Now& n = plan.now[u.i32(0)];
        n.stored = u.str(1);
        n.text = n.stored;
    });
}

// Each piece in order, as save_one(piece, kHead, import) would find it.
Result<std::vector<SaveResult>> Store::plan_import(const std::vector<Piece>& pieces,
                                                   const std::vector<Header>& headers,
                                                   ImportPlan& plan, const std::string& what) {
    Result<std::vector<SaveResult>> r;
    r.value.reserve(pieces.size());
    for (size_t i = 0; i < pieces.size(); ++i) {
        const Piece& p = pieces[i];
        ImportPlan::Now& n = plan.now[p.number];
        ProgramRow& row = n.row;
        SaveResult out;
        out.number = p.number;
        const bool maybe = row.found && !row.deleted && row.size == int64_t(p.text.size());
        if (maybe && !n.text) {  // its current revision is missing
            r.error = fail(db::kCorrupt, what);
            return r;
        }
        if (maybe && *n.text == std::string_view(p.text)) {
            out.status = SaveStatus::unchanged;
            out.revision = out.current = row.head;
            out.current_by = row.modified_by;
            if (row.conflict) plan.cleared.push_back(p.number);
            row.conflict = 0;
            r.value.push_back(std::move(out));
            continue;
        }
        const int rev = row.found ? row.last + 1 : 1;
        const int64_t lines = count_lines(p.text), at = now_ms();
        plan.revisions.push_back({&p, rev, row.head, lines, at});
        const Header& h = headers[i];
        plan.heads[p.number] = {h.index >= 0 ? std::optional<int64_t>(h.index) : std::nullopt,
                                h.title,
                                rev,
                                int64_t(p.text.size()),
                                lines,
                                at};
        out.status = (!row.found || row.deleted) ? SaveStatus::created : SaveStatus::saved;
        out.revision = out.current = rev;
        out.current_by = user_;
        row = ProgramRow{true, rev, rev, 0, false, int64_t(p.text.size()), user_};
        n.text = p.text;
        r.value.push_back(std::move(out));
    }
    return r;
}

// The plan's revisions and the rows of its new programs through
// Backend::insert_rows; the rows of programs the store held through
// multi-row upserts; the conflicts an unchanged text settles.
StoreError Store::write_import(const ImportPlan& plan) {
    // A failure is named after the first program of what failed.
    auto failed = [&](int rc, int number) {
        return fail(rc, strf(tr("cannot save %%%d"), number));
    };
    using Value = db::Value;
    auto num = [](int64_t v) { return Value{Value::Kind::integer, v, {}}; };
    auto str = [](std::string_view t) { return Value{Value::Kind::text, 0, t}; };
    std::vector<Value> v;
    v.reserve(plan.revisions.size() * 11);
    for (const ImportPlan::Revision& r : plan.revisions) {
        const std::string& text = r.piece->text;
        v.insert(v.end(), {num(r.piece->number), num(r.rev), str(kind_name(RevisionKind::import)),
                           num(r.base), num(0), Value{Value::Kind::bytes, 0, text},
                           num(int64_t(text.size())), num(r.lines), str(user_), num(r.at_ms),
                           str(r.piece->source)});
    }
    if (!v.empty())
        if (int rc = db_->insert_rows("revisions", kRevisionColumns, 11, v))
            return failed(rc, plan.revisions[0].piece->number);
    v.clear();
    std::vector<std::pair<int, const ImportPlan::Head*>> held;
    for (const auto& [number, h] : plan.heads) {
        if (plan.now.at(number).in_table) {
            held.emplace_back(number, &h);
            continue;
        }
        v.insert(v.end(), {num(number), h.index ? num(*h.index) : Value{}, str(h.title), num(h.rev),
                           num(h.rev), Value{}, num(0), num(h.size), num(h.lines), num(h.at_ms),
                           str(user_)});
    }
    if (!v.empty())
        if (int rc = db_->insert_rows("programs", kProgramColumns, 11, v))
            return failed(rc, int(v[0].integer));
    StoreError e = sql::in_batches(held.size(), [&](size_t at, size_t n) {
        sql::Use u = use(sql::repeated(kUpsertPrograms, kProgramRow, 8, int(n), kUpsertTail));
        if (u.error) return u.error;
        for (size_t i = 0; i < n; ++i) {
            const auto& [number, h] = held[at + i];
            const int k = int(i) * 8;
            u.bind(k + 1, number).bind(k + 3, h->title).bind(k + 4, h->rev);
            bind_value(u, k + 2, h->index);
            u.bind(k + 5, h->size).bind(k + 6, h->lines).bind(k + 7, h->at_ms).bind(k + 8, user_);
        }
        int rc = u.step();
        return rc == db::kDone ? StoreError{} : failed(rc, held[at].first);
    });
    if (e) return e;
    if (plan.cleared.empty()) return {};
    return for_numbers(kClearConflicts, plan.cleared, strf(tr("cannot save %%%d"), plan.cleared[0]),
                       [](const sql::Use&) {});
}

Result<std::vector<SaveResult>> Store::save_all(const std::vector<Piece>& pieces) {
    Result<std::vector<SaveResult>> r;
    std::vector<Header> headers(pieces.size());
    for (size_t i = 0; i < pieces.size(); ++i)
        if ((r.error = check_number(pieces[i], path_, headers[i]))) return r;
    if (pieces.empty()) return r;
    const std::string what = strf(tr("cannot save %%%d"), pieces[0].number);
    return in_write([&] {
        ImportPlan plan;
        Result<std::vector<SaveResult>> out;
        if ((out.error = read_import(pieces, plan, what))) return out;
        out = plan_import(pieces, headers, plan, what);
        if (!out.error) out.error = write_import(plan);
        if (out.error) out.value.clear();
        return out;
    });
}

Result<SaveResult> Store::remove(int number, int based_on, std::string_view source) {
    const std::string what = strf(tr("cannot delete %%%d"), number);
    return in_write([&] {
        Result<SaveResult> r;
        r.value.number = number;
        ProgramRow row;
        if ((r.error = read_row(number, row, what))) return r;
        if (!row.found || row.deleted) {
            r.error = {Fault::not_found,
                       strf(tr("%s: no program %%%d in the store"), path_.c_str(), number)};
            return r;
        }
        if (based_on != kHead && based_on != row.head) {
            // Deleting what someone changed since it was loaded: refused,
            // nothing lost (and nothing written: the commit changes nothing).
            r.value.status = SaveStatus::conflict;
            r.value.current = row.head;
            r.value.current_by = row.modified_by;
            return r;
        }
        const int rev = row.last + 1;
        if ((r.error = insert_revision(number, rev, RevisionKind::remove, row.head, false, nullptr,
                                       std::string(source), what)))
            return r;
        if ((r.error = update_program(kDelete, what, number, rev, now_ms(), user_))) return r;
        r.value.status = SaveStatus::saved;
        r.value.revision = r.value.current = rev;
        r.value.current_by = user_;
        r.value.deleted = true;
        return r;
    });
}

// The text of revision `revision` of a program, for restore: not_found when
// there is none, bad_data when it is the deletion.
Result<std::string> Store::revision_text(int number, int revision, const std::string& what) {
    Result<std::string> r;
    sql::Use u = use(kSelectText);
    if ((r.error = u.error)) return r;
    int rc = u.bind(1, number).bind(2, revision).step();
    if (rc == db::kDone)
        r.error = {Fault::not_found,
                   strf(tr("%s: no revision %d of %%%d"), path_.c_str(), revision, number)};
    else if (rc != db::kRow)
        r.error = fail(rc, what);
    else if (u.is_null(0))
        r.error = {Fault::bad_data,
                   strf(tr("%s: revision %d of %%%d is its deletion; restore a revision before it"),
                        path_.c_str(), revision, number)};
    else
        r.value = u.str(0);
    return r;
}

Result<SaveResult> Store::restore(int number, int revision, std::string_view source) {
    const std::string what = strf(tr("cannot restore %%%d"), number);
    std::string src = source.empty() ? "restore r" + std::to_string(revision) : std::string(source);
    return in_write([&] {
        Result<std::string> text = revision_text(number, revision, what);
        if (text.error) {
            Result<SaveResult> r;
            r.value.number = number;
            r.error = text.error;
            return r;
        }
        return save_one(Piece{number, std::move(text.value), src}, kHead, RevisionKind::restore);
    });
}

// In number order, put here rather than asked of the engine: read in the
// table's order the rows come as they were written, mostly in order already,
// whatever the server's planner knows of the table (right after an import of
// 10,000 programs, before autovacuum has made its statistics, it would scan
// and sort them: twice the time). The rows come by use_many: from a server,
// as one binary COPY.
Result<std::vector<ProgramInfo>> Store::list() {
    Result<std::vector<ProgramInfo>> r;
    static const std::string sql =
        std::string("SELECT ") + kListColumns + " FROM programs WHERE deleted = 0";
    const char* packed = db_->packed_list();
    StoreError e;
    sql::Use u = use_many(packed ? packed : sql.c_str());
    e = u.error;
    if ((r.error = e)) return r;
    int rc;
    while ((rc = u.step()) == db::kRow) {
        if (!packed) {
            read_info(u, r.value.emplace_back(), true);
        } else if (!read_packed(u, r.value.emplace_back())) {
            r.value.clear();
            r.error = {Fault::bad_data,
                       strf(tr("%s: cannot list the programs: the store is damaged (a program's "
                               "list entry is not 56 bytes); nothing was changed: restore a "
                               "backup"),
                            path_.c_str())};
            return r;
        }
    }
    if (rc != db::kDone) {
        r.value.clear();
        r.error = fail(rc, tr("cannot list the programs"));
    }
    in_number_order(r.value);
    return r;
}

Result<Program> Store::read(int number, int revision) {
    Result<Program> r;
    static const std::string info_sql =
        std::string("SELECT ") + kInfoColumns + " FROM programs WHERE number = ?1";
    const std::string what = strf(tr("cannot read %%%d"), number);
    // Two statements, one snapshot.
    if ((r.error = begin_read())) return r;
    StoreError e;
    bool found = false;
    {
        sql::Use u = use(info_sql.c_str());
        e = u.error;
        if (!e) {
            int rc = u.bind(1, number).step();
            if (rc == db::kRow) {
                found = true;
                r.value.info = info_of(u);
            } else if (rc != db::kDone) {
                e = fail(rc, what);
            }
        }
    }
    if (!e && !found)
        e = {Fault::not_found, strf(tr("%s: no program %%%d in the store"), path_.c_str(), number)};
    if (!e && revision == 0 && r.value.info.deleted)
        e = {Fault::not_found,
             strf(tr("%s: %%%d was deleted (revision %d); its history keeps the earlier revisions"),
                  path_.c_str(), number, r.value.info.revision)};
    const int rev = revision == 0 ? r.value.info.revision : revision;
    if (!e) {
        sql::Use u = use(kSelectText);
        e = u.error;
        if (!e) {
            int rc = u.bind(1, number).bind(2, rev).step();
            if (rc == db::kRow && !u.is_null(0)) {
                r.value.text = u.str(0);
                r.value.revision = rev;
            } else if (rc == db::kRow) {
                e = {Fault::not_found, strf(tr("%s: revision %d of %%%d is its deletion"),
                                            path_.c_str(), rev, number)};
            } else if (rc == db::kDone) {
                e = {Fault::not_found,
                     strf(tr("%s: no revision %d of %%%d"), path_.c_str(), rev, number)};
            } else {
                e = fail(rc, what);
            }
        }
    }
    rollback();  // a read: nothing to keep
    if (e) r = Result<Program>{{}, e};
    return r;
}

StoreError Store::each_program(const std::function<void(int, std::string_view)>& f) {
    StoreError e;
    sql::Use u =
        use("SELECT p.number, r.text FROM programs p JOIN revisions r "
            "ON r.program = p.number AND r.rev = p.head WHERE p.deleted = 0 ORDER BY p.number");
    e = u.error;
    if (e) return e;
    int rc;
    while ((rc = u.step()) == db::kRow) f(u.i32(0), u.view(1));
    return rc == db::kDone ? StoreError{} : fail(rc, tr("cannot read the programs"));
}

Result<std::vector<RevisionInfo>> Store::history(int number) {
    Result<std::vector<RevisionInfo>> r;
    constexpr const char* kHistory =
        "SELECT rev, kind, based_on, conflict, at_ms, who, source, size, lines FROM revisions "
        "WHERE program = ?1 ORDER BY rev";
    StoreError e;
    sql::Use u = use(kHistory);
    e = u.error;
    if ((r.error = e)) return r;
    u.bind(1, number);
    int rc;
    while ((rc = u.step()) == db::kRow) {
        RevisionInfo i;
        i.revision = u.i32(0);
        i.kind = kind_of(u.view(1));
        i.based_on = u.i32(2);
        i.conflict = u.i32(3) != 0;
        i.at_ms = u.i64(4);
        i.who = u.str(5);
        i.source = u.str(6);
        i.size = u.i64(7);
        i.lines = u.i64(8);
        r.value.push_back(std::move(i));
    }
    if (rc != db::kDone) {
        r.value.clear();
        r.error = fail(rc, strf(tr("cannot read the history of %%%d"), number));
    } else if (r.value.empty()) {
        r.error = {Fault::not_found,
                   strf(tr("%s: no program %%%d in the store"), path_.c_str(), number)};
    }
    return r;
}

}  // namespace pupitre::store
