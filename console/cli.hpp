// The batch commands of the pupitre executable (pupitre(1), OPTIONS).
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <memory>
#include <string>
#include <vector>

namespace pupitre {
class ProgramMemory;
struct MachineProfile;
struct Diag;
class Interpreter;
namespace store {
class Store;
struct StoreError;
}  // namespace store
namespace workshop {
struct Setup;
}
}  // namespace pupitre

namespace pupitre::cli {

// sysexits(3)
inline constexpr int kOk = 0, kProgramErrors = 1, kUsage = 64, kDataErr = 65, kNoInput = 66,
                     kSoftware = 70, kCantCreate = 73, kIoErr = 74, kNoPerm = 77;

// One default machine for every batch command and the console's first start
// is the lathe. A batch command never depends on what the console used last
// (docs/decisions.md, The default machine is the lathe).
inline constexpr const char* kDefaultMachine = "lathe";

struct RunArgs {
    std::string machine;            // "": kDefaultMachine
    std::vector<std::string> sets;  // NAME=VALUE
    std::vector<std::string> files;
    bool trace = false;
    bool json = false;
    bool block_skip = false;
    bool optional_stop = false;
    long max_blocks = 20'000'000;
    std::string db;  // --db: the store is program memory and machine state
    // The workshop (pupitre-setup(5)): a setup's name or file, the
    // measurements to take after the run, where to write the part.
    std::string setup;
    std::vector<std::string> measures;
    std::string part_out;
    std::string part_view;  // --part-view: section, top or 3d (a picture)
    // --edge-life: the life of an edge, MINUTES or TN=MINUTES (core/plan/tools.hpp).
    std::vector<std::string> edge_life;
    bool no_plan = false;  // --no-plan: the time at the feeds alone, no planner
};

int run(const RunArgs& a);
// Shared by run, check and plot (cli_run.cpp). Each prints its problems.
void print_diag(const Diag& d);
int load_all(const std::vector<std::string>& files, ProgramMemory& mem);  // an exit code
int apply_sets(const std::vector<std::string>& sets, Interpreter& in);    // --set; an exit code
// A built-in profile or a .machine file; prints the problem and returns false.
bool load_machine(const std::string& name, MachineProfile& m);
// The machine a batch command runs on: --machine, else the default.
inline std::string batch_machine(const std::string& asked) {
    return asked.empty() ? kDefaultMachine : asked;
}
// --setup: a shipped setup's name or a setup file (pupitre-setup(5)); prints
// the problem and returns false.
bool load_setup(const std::string& name, const MachineProfile& m, workshop::Setup& s);
// After a run with errors on the default machine, says which machine ran.
void default_machine_note(const std::string& asked, bool errors);

// The console (console/app.cpp): pupitre with no command.
struct ConsoleArgs {
    std::string db;
    std::string machine;  // "" = the last one used, else lathe
    std::string theme;    // empty: colour, or mono when NO_COLOR is set (no-color.org)
    bool ascii = false;   // no UTF-8 line drawing even on a UTF-8 terminal
    // An exercise's attempt (pupitre exercise NAME): its name and the student.
    std::string exercise, student;
};
int console(const ConsoleArgs& a);
int check(const RunArgs& a);

// The store commands (cli_store.cpp). `db` empty: the default store.
struct StoreArgs {
    std::string db;
    std::vector<std::string> files;  // import
    int number = -1;                 // import --number, for a file with no % line
    std::vector<int> numbers;        // export N..., rm N, history N, restore N REV
    int revision = 0;                // restore
    std::string output;              // export -o
    std::string from, to;            // store copy FROM TO
};

// Prints a store's error; its exit code.
int report(const store::StoreError& e);
// The store named by --db, or the default one (its directory made if needed).
int open_store(const std::string& db, std::unique_ptr<store::Store>& out);

// Training (cli_exercise.cpp, pupitre-exercise(5)): `pupitre exercise
// list|check FILE...|add FILE|truth NAME|save NAME`, or NAME to open the
// console on it; `pupitre class report [EXERCISE]`.
struct ExerciseArgs {
    std::string db;
    std::vector<std::string> words;
    std::string student;  // --student
    std::string machine;  // save: the machine whose setup
    std::string output;   // save -o, report --html
    std::string pdf;      // report --pdf
    bool csv = false;
    std::string group = "class";  // class --class: the class (a group role on the server)
    bool group_given = false;
    std::string from;  // class add-student --from FILE.csv
    ConsoleArgs console;
};
int exercise(const ExerciseArgs& a);
int class_report(const ExerciseArgs& a);
// class report|init|add-student|students|grade|replay (cli_class.cpp).
int class_command(const ExerciseArgs& a);
// class watch: the teacher's live view (watch.cpp).
int class_watch(const ExerciseArgs& a, store::Store& st);
// class replay ATTEMPT: the console, read-only, on its replay (replay_console.cpp).
int class_replay(const ExerciseArgs& a, store::Store& st);

int store_import(const StoreArgs& a);
int store_export(const StoreArgs& a);
int store_list(const StoreArgs& a);
int store_rm(const StoreArgs& a);
int store_history(const StoreArgs& a);
int store_restore(const StoreArgs& a);
int store_copy(const StoreArgs& a);

// The store of one `run` or `check --db` (cli_store.cpp). Each call prints its
// problems and returns an exit code, 0 when all is well.
class RunStore {
  public:
    RunStore();
    ~RunStore();
    int open(const std::string& db);
    // Stored programs become program memory after the files (G77 H).
    int load_programs(ProgramMemory& mem);
    // The stored correctors and origins of the machine, before --set.
    int seed(Interpreter& in);
    // The run's writes to correctors and origins, kept with an audit row each.
    int persist(const Interpreter& in, const std::string& file, const std::string& machine_arg);

  private:
    std::unique_ptr<store::Store> s_;
};

}  // namespace pupitre::cli
