// Never lose typed work (issue 12.4): the editor's recovery journal and the
// questions before unsaved changes are dropped.
//
// Like vim's swap files, every change to a program open in EDIT writes the
// whole text to a journal beside the store (STORE.recover/N.iso, written to a
// temporary file, synced and renamed: a kill -9 or a dropped SSH connection
// loses at most the line being typed). :save, and a drop the operator
// confirmed, remove it. The next :edit N (and the start message) offers the
// text: :recover loads it, :discard drops it.
// SPDX-License-Identifier: GPL-3.0-or-later
#include <dirent.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <sstream>

#include "console/edit.hpp"
#include "core/i18n.hpp"
#include "store/store.hpp"

namespace pupitre::console {

namespace {

// The first line of a journal names what it recovers.
constexpr const char* kHeader = "(PUPITRE RECOVERY OF %%%d BASED ON REVISION %d)\n";

bool write_all(int fd, const std::string& s) {
    size_t done = 0;
    while (done < s.size()) {
        ssize_t n = ::write(fd, s.data() + done, s.size() - done);
        if (n <= 0) return false;
        done += size_t(n);
    }
    return true;
}

}  // namespace

std::string EditDesk::journal_dir() const {
    if (!b_.store()) return {};
    std::string local = b_.store()->local_path();  // a server's store: a directory of this PC
    if (local.empty() || local[0] == ':') return {};
    return local + ".recover";
}

std::string EditDesk::journal_path(int number) const {
    std::string dir = journal_dir();
    return dir.empty() ? dir : dir + "/" + std::to_string(number) + ".iso";
}

// After every key: a change made to the program in EDIT goes to its journal.
void EditDesk::sync_journal() {
    if (!editor_.is_open() || modif_ || editor_.changes == journaled_changes_) return;
    journaled_changes_ = editor_.changes;
    std::string path = journal_path(editor_.number);
    if (path.empty()) return;
    // A server's journal lives under this PC's data directory: make its parents.
    const std::string dir = journal_dir();
    for (size_t slash = dir.find('/', 1); slash != std::string::npos;
         slash = dir.find('/', slash + 1))
        ::mkdir(dir.substr(0, slash).c_str(), 0700);
    ::mkdir(dir.c_str(), 0700);
    char head[96];
    std::snprintf(head, sizeof head, kHeader, editor_.number, editor_.revision);
    std::string tmp = path + ".tmp";
    int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
    bool ok = fd >= 0 && write_all(fd, head + editor_.text()) && ::fsync(fd) == 0;
    if (fd >= 0) ::close(fd);
    if (!ok || ::rename(tmp.c_str(), path.c_str()) != 0) {
        ::unlink(tmp.c_str());
        b_.say(strf(tr("the recovery journal cannot be written (%s): :save often"),
                    journal_dir().c_str()),
               true);
    }
}

void EditDesk::drop_journal(int number) {
    std::string path = journal_path(number);
    if (!path.empty()) ::unlink(path.c_str());
}

// The journal of a program: its text and base revision; false if none.
bool EditDesk::read_journal(int number, std::string& text, int& base) const {
    std::string path = journal_path(number);
    if (path.empty()) return false;
    std::ifstream f(path, std::ios::binary);
    if (!f) return false;
    std::string head;
    if (!std::getline(f, head)) return false;
    int n = -1;
    base = 0;
    if (std::sscanf(head.c_str(), "(PUPITRE RECOVERY OF %%%d BASED ON REVISION %d)", &n, &base) !=
            2 ||
        n != number)
        return false;
    std::stringstream ss;
    ss << f.rdbuf();
    text = ss.str();
    return true;
}

// Programs with a journal left by an earlier session, for the start message.
std::string EditDesk::recovered_note() const {
    std::string dir = journal_dir();
    DIR* d = dir.empty() ? nullptr : ::opendir(dir.c_str());
    if (!d) return {};
    std::string list;
    int first = -1;
    while (dirent* e = ::readdir(d)) {
        std::string name = e->d_name;
        if (name.size() < 5 || name.substr(name.size() - 4) != ".iso") continue;
        int n = std::atoi(name.c_str());
        if (first < 0) first = n;
        list += (list.empty() ? "%" : ", %") + std::to_string(n);
    }
    ::closedir(d);
    if (list.empty()) return {};
    return strf(tr("unsaved work recovered for %s: :edit %d, then :recover"), list.c_str(), first);
}

// The editor's unsaved work when a signal ends the console (app.cpp):
// where it is, for stderr; "" when there is none.
std::string EditDesk::unsaved_note() const {
    if (!editor_.is_open() || !editor_.dirty) return {};
    const int n = editor_.number;
    if (modif_) return strf(tr("the MODIF changes of %%%d are lost"), n);
    std::string path = journal_path(n);
    if (path.empty() || ::access(path.c_str(), F_OK) != 0)
        // A new program's % line alone is no work; anything else had no journal.
        return editor_.lines().size() <= 1
                   ? std::string()
                   : strf(tr("the unsaved changes of %%%d are lost (no journal)"), n);
    return strf(tr("the unsaved changes of %%%d are in the recovery journal %s: :edit %d, then "
                   ":recover"),
                n, path.c_str(), n);
}

// On :edit N: a journal that differs from the text loaded is offered.
void EditDesk::offer_journal(int number, const std::string& loaded) {
    std::string text;
    int base = 0;
    if (!read_journal(number, text, base)) return;
    if (text == loaded) {
        drop_journal(number);
        return;
    }
    journal_held_ = number;  // no change may write over it before the operator chooses
    b_.say(
        strf(tr("%%%d has unsaved changes from an earlier session: :recover loads them, :discard "
                "drops them"),
             number),
        true);
}

// A key while an earlier session's journal waits for :recover or :discard:
// a change to the text would write the journal over, so it is undone and
// refused. Only then is the editor copied (a rare moment): the Session keeps
// `before` around the key.
void EditDesk::refuse_changes_since(const Editor& before) {
    if (journal_held_ == before.number && editor_.is_open() && editor_.number == before.number &&
        editor_.changes != before.changes) {
        editor_ = before;
        b_.say(strf(tr("%%%d: an earlier session's changes wait: :recover or :discard them first"),
                    before.number),
               true);
    }
}

bool EditDesk::held() const {
    return journal_held_ >= 0 && editor_.is_open() && !modif_ && editor_.number == journal_held_;
}

// :recover and :discard, on the program open in EDIT.
Effect EditDesk::recover(bool discard) {
    if (!editor_.is_open() || modif_) {
        b_.say(tr("open the program first: :edit N"), true);
        return Effect::redraw;
    }
    int n = editor_.number;
    std::string text;
    int base = 0;
    if (!read_journal(n, text, base)) {
        b_.say(strf(tr("%%%d has no recovered changes"), n), true);
        return Effect::redraw;
    }
    journal_held_ = -1;
    if (discard) {
        drop_journal(n);
        b_.say(strf(tr("recovered changes of %%%d dropped"), n));
        return Effect::redraw;
    }
    editor_.open(n, text, base, false);
    editor_.dirty = true;
    ++editor_.changes;
    sync_journal();
    b_.say(strf(tr("%%%d: recovered text loaded (based on revision %d); :save keeps it"), n, base));
    return Effect::redraw;
}

// :quit, Ctrl-C: unsaved changes in EDIT are dropped only when the operator
// says so (or :quit!). The journal goes with them.
bool EditDesk::asks_before_quit(std::function<void()> quit) {
    if (!editor_.is_open() || !editor_.dirty || modif_) return false;
    int n = editor_.number;
    b_.confirm(
        strf(tr("%%%d has unsaved changes: quit and drop them? (:save first, or :quit!)"), n),
        [this, n, quit = std::move(quit)] {
            drop_journal(n);
            release_lease();
            quit();
        });
    return true;
}

void EditDesk::leave(bool force) {
    // Only the editor's own journal: a clean editor's is an earlier session's.
    if (force && editor_.is_open() && editor_.dirty && !modif_) drop_journal(editor_.number);
    release_lease();
}

}  // namespace pupitre::console
