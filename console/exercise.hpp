// The console's side of training (issue 16, pupitre-exercise(5)): the class's
// key, finding an exercise, the part scrambled in the store and the
// attempt's signature. The attempt itself is the exercise run
// (exercise_run.hpp); no page, command, trace or log shows its truth before
// :submit.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "core/training/grade.hpp"
#include "store/store.hpp"

namespace pupitre::console {

// The class's key file: $PUPITRE_CLASS_KEY, else
// $XDG_CONFIG_HOME/pupitre/class.key, else ~/.config/pupitre/class.key.
std::string class_key_path();
// Reads the key into `key`; when the file does not exist and `create`,
// makes one (mode 0600, 32 random bytes in hex). "" or what went wrong.
std::string class_key(bool create, std::string& key);
// The teacher's key on one PC (pupitre-exercise(5), THE CLASS KEY): a file
// apart from the class key, that the students' accounts cannot read:
// $PUPITRE_TEACHER_KEY, else $XDG_CONFIG_HOME/pupitre/teacher.key, else
// ~/.config/pupitre/teacher.key.
std::string teacher_key_path();
// class init on a file: makes the teacher's key when missing and records its
// fingerprint in the store. "" or why not.
std::string init_teacher_key(store::Store& st);
// exercise truth on a file: once the store has a teacher's key, only its
// holder draws a student's truth. "" or why not.
std::string teacher_allowed(store::Store& st);
// The class key for work on the store `st`. The store keeps the key's
// fingerprint from its first attempt on: a key that is not the store's (one
// made on a student's own account, on a shared store) is refused at once,
// rather than graded TAMPERED with a truth the teacher cannot draw again.
// `create`: make a key when neither the store nor the user has one.
std::string store_class_key(store::Store& st, bool create, std::string& key);
// exercise truth of `student`'s attempt at `e`: while it is in progress,
// for the owner of the class key's file only (`caller`, a uid); a user who
// can only read the key (a setgid pupitre on a shared server) sees it once
// the attempt is submitted. "" or why not.
std::string truth_allowed(store::Store& st, const training::Exercise& e, const std::string& student,
                          unsigned caller);

// A name that is a file: a '/' in it, or ending in .exercise.
bool exercise_is_file(const std::string& name);
// An exercise by name (the store's, then the shipped ones) or a file
// (a name with a '/' or ending in .exercise). "" or what is wrong.
std::string find_exercise(store::Store* st, const std::string& name, training::Exercise& e);

// The student: `asked`, else the OS user.
std::string student_name(const std::string& asked);

// The workshop's part as the store keeps it during an exercise: scrambled
// with the seed, so that the part's outline in machine coordinates (which
// gives the stock's place away) is not there for sqlite3 to show.
std::string scramble(const std::string& text, uint64_t seed);
std::string unscramble(const std::string& text, uint64_t seed);

// The readings and shims of an attempt's record (record.hpp): its "dia"
// and "shim" notes, in either version of the record.
training::Context record_context(const std::string& text);

// The signature of a graded attempt: HMAC-SHA-256 of its fields with the key
// (the record too, when it has one: a record-less attempt signs as before).
std::string sign_attempt(const store::Attempt& a, const std::string& key);

}  // namespace pupitre::console
