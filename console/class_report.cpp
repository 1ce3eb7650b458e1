// The teacher's report (see class_report.hpp).
// SPDX-License-Identifier: GPL-3.0-or-later
#include "console/class_report.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include "console/exercise.hpp"
#include "core/i18n.hpp"
#include "pages/pages.hpp"

namespace pupitre::console {

namespace {

// One student at one exercise.
struct Row {
    std::string exercise, student;
    int attempts = 0, in_progress = 0, best = -1, last = -1, crashes = 0, scrapped = 0;
    double best_seconds = 0;
    bool tampered = false;
    int ungraded = 0;               // on a class's server: submitted, not yet graded and signed
    std::set<std::string> earlier;  // the texts (SHA-256, 8 digits) not the exercise's current
    std::map<std::string, int> mistakes;
};

std::vector<Row> rows_of(const std::vector<store::Attempt>& all, const ReportContext& c,
                         std::map<std::string, int>& mistakes) {
    const std::string& key = c.key;
    const bool on_server = c.on_server;
    std::map<std::pair<std::string, std::string>, Row> by;
    for (const store::Attempt& a : all) {
        Row& r = by[{a.exercise, a.student}];
        r.exercise = a.exercise, r.student = a.student;
        if (auto now = c.current.find(a.exercise);
            now != c.current.end() && now->second != a.exercise_sha)
            r.earlier.insert(a.exercise_sha.substr(0, 8));
        if (a.submitted_ms == 0) {
            ++r.in_progress;
            continue;
        }
        ++r.attempts;
        if (on_server && a.signature.empty()) {
            ++r.ungraded;
            continue;
        }
        // An attempt edited in the store counts for nothing: neither its
        // score nor its time, crashes or mistakes; the row says TAMPERED.
        if (!key.empty() && sign_attempt(a, key) != a.signature) {
            r.tampered = true;
            continue;
        }
        r.last = a.score;
        if (a.score > r.best || (a.score == r.best && a.seconds < r.best_seconds))
            r.best = a.score, r.best_seconds = a.seconds;
        r.crashes += a.crashes;
        r.scrapped += a.scrapped;
        // Counted once an attempt: DEC1 forgotten on X and on Z is one
        // student's one mistake, not two.
        std::istringstream words(a.mistakes);
        std::set<std::string> once;
        for (std::string w; words >> w;) once.insert(w);
        for (const std::string& w : once) ++r.mistakes[w], ++mistakes[w];
    }
    std::vector<Row> out;
    for (auto& [k, r] : by) out.push_back(r);
    return out;
}

std::string minutes(double s) {
    return s > 0 ? strf("%.1f", s / 60) : "-";
}

std::string score(int s) {
    return s < 0 ? "-" : std::to_string(s);
}

std::string common_mistakes(const std::map<std::string, int>& m) {
    std::vector<std::pair<int, std::string>> v;
    for (const auto& [w, n] : m) v.emplace_back(-n, w);
    std::sort(v.begin(), v.end());
    std::string out;
    for (const auto& [n, w] : v)
        out += (out.empty() ? "" : " ") + w + "\u00d7" + std::to_string(-n);
    return out;
}

// The mistakes' words in the store, with their titles.
std::string mistake_text(const std::string& word) {
    for (int i = 1; i <= int(training::Mistake::unset); ++i)
        if (word == training::mistake_id(training::Mistake(i)))
            return training::mistake_title(training::Mistake(i));
    return word;
}

std::string html_escape(const std::string& s) {
    std::string o;
    for (char c : s) {
        if (c == '<')
            o += "&lt;";
        else if (c == '>')
            o += "&gt;";
        else if (c == '&')
            o += "&amp;";
        else if (c == '"')
            o += "&quot;";
        else
            o += c;
    }
    return o;
}

std::string earlier_html(const Row& r) {
    std::string out;
    for (const std::string& t : r.earlier)
        out += " " + html_escape(strf(tr("EARLIER TEXT %s"), t.c_str()));
    return out;
}

std::string table(const std::vector<Row>& rows, const std::map<std::string, int>& mistakes,
                  const std::string& key) {
    std::string out = pages::pad(tr("EXERCISE"), 16) + " " + pages::pad(tr("STUDENT"), 14) +
                      strf(" %8s %6s %6s %8s %7s %8s  %s\n", tr("ATTEMPTS"), tr("BEST"), tr("LAST"),
                           tr("MIN"), tr("CRASHES"), tr("SCRAPPED"), tr("MISTAKES"));
    for (const Row& r : rows) {
        std::string n = std::to_string(r.attempts) + (r.in_progress ? "+" : "");
        // Names padded by columns: a student's name may hold "é".
        std::string line =
            pages::pad(r.exercise, 16) + " " + pages::pad(r.student, 14) +
            strf(" %8s %6s %6s %8s %7d %8d  %s%s", n.c_str(), score(r.best).c_str(),
                 score(r.last).c_str(), minutes(r.best_seconds).c_str(), r.crashes, r.scrapped,
                 common_mistakes(r.mistakes).c_str(), r.tampered ? tr("  TAMPERED") : "");
        if (r.ungraded) line += strf(tr("  UNGRADED %d"), r.ungraded);
        for (const std::string& t : r.earlier) line += strf(tr("  EARLIER TEXT %s"), t.c_str());
        while (!line.empty() && line.back() == ' ') line.pop_back();
        out += line + "\n";
    }
    out += "\n" + std::string(tr("Mistakes most made:")) + "\n";
    if (mistakes.empty()) out += "  " + std::string(tr("no mistake")) + "\n";
    std::vector<std::pair<int, std::string>> v;
    for (const auto& [w, n] : mistakes) v.emplace_back(-n, w);
    std::sort(v.begin(), v.end());
    for (const auto& [n, w] : v) out += strf("  %3d  %s\n", -n, mistake_text(w).c_str());
    if (key.empty()) out += std::string(tr("Signatures not checked: no class key.")) + "\n";
    return out;
}

std::string csv(const std::vector<Row>& rows) {
    auto q = [](const std::string& s) {
        std::string o = "\"";
        for (char c : s) o += c == '"' ? std::string("\"\"") : std::string(1, c);
        return o + "\"";
    };
    std::string out =
        "exercise,student,attempts,in_progress,best,last,best_minutes,crashes,scrapped,"
        "tampered,mistakes\n";
    for (const Row& r : rows)
        out +=
            strf("%s,%s,%d,%d,%s,%s,%s,%d,%d,%d,%s\n", q(r.exercise).c_str(), q(r.student).c_str(),
                 r.attempts, r.in_progress, r.best < 0 ? "" : std::to_string(r.best).c_str(),
                 r.last < 0 ? "" : std::to_string(r.last).c_str(),
                 r.best_seconds > 0 ? minutes(r.best_seconds).c_str() : "", r.crashes, r.scrapped,
                 r.tampered ? 1 : 0, q(common_mistakes(r.mistakes)).c_str());
    return out;
}

std::string html(const std::vector<Row>& rows, const std::map<std::string, int>& mistakes,
                 const std::string& key, const std::string& title) {
    std::string out =
        "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>" + html_escape(title) +
        "</title>\n<style>body{font-family:sans-serif;margin:2em}table{border-collapse:collapse}"
        "td,th{border:1px solid #888;padding:.2em .6em;text-align:left}"
        "td.n{text-align:right}.bad{color:#b00;font-weight:bold}"
        "@media print{body{margin:0}}</style></head><body>\n<h1>" +
        html_escape(title) + "</h1>\n<table>\n<tr>";
    for (const char* h : {N_("Exercise"), N_("Student"), N_("Attempts"), N_("Best"), N_("Last"),
                          N_("Minutes (best)"), N_("Crashes"), N_("Scrapped"), N_("Mistakes")})
        out += "<th>" + html_escape(tr(h)) + "</th>";
    out += "</tr>\n";
    for (const Row& r : rows) {
        out +=
            "<tr><td>" + html_escape(r.exercise) + "</td><td>" + html_escape(r.student) +
            "</td><td class=\"n\">" + std::to_string(r.attempts) + (r.in_progress ? "+" : "") +
            "</td><td class=\"n\">" + score(r.best) + "</td><td class=\"n\">" + score(r.last) +
            "</td><td class=\"n\">" + minutes(r.best_seconds) + "</td><td class=\"n\">" +
            std::to_string(r.crashes) + "</td><td class=\"n\">" + std::to_string(r.scrapped) +
            "</td><td>" + html_escape(common_mistakes(r.mistakes)) +
            (r.tampered ? " <span class=\"bad\">" + html_escape(tr("TAMPERED")) + "</span>" : "") +
            (r.ungraded ? " " + html_escape(strf(tr("UNGRADED %d"), r.ungraded)) : "") +
            earlier_html(r) + "</td></tr>\n";
    }
    out += "</table>\n<h2>" + html_escape(tr("Mistakes most made")) + "</h2>\n<ol>\n";
    std::vector<std::pair<int, std::string>> v;
    for (const auto& [w, n] : mistakes) v.emplace_back(-n, w);
    std::sort(v.begin(), v.end());
    for (const auto& [n, w] : v)
        out += "<li>" + html_escape(mistake_text(w)) + " (" + std::to_string(-n) + ")</li>\n";
    out += "</ol>\n";
    if (key.empty())
        out += "<p>" + html_escape(tr("Signatures not checked: no class key.")) + "</p>\n";
    return out + "</body></html>\n";
}

}  // namespace

std::string class_report_text(const std::vector<store::Attempt>& attempts, ReportFormat f,
                              const ReportContext& c) {
    const std::string& key = c.key;
    const std::string& title = c.title;
    std::map<std::string, int> mistakes;
    const std::vector<Row> rows = rows_of(attempts, c, mistakes);
    switch (f) {
        case ReportFormat::csv:
            return csv(rows);
        case ReportFormat::html:
            return html(rows, mistakes, key, title);
        case ReportFormat::table:
            break;
    }
    return table(rows, mistakes, key);
}

}  // namespace pupitre::console
