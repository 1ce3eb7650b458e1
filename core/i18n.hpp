// The language people read: GNU gettext catalogues (po/LANG.po, compiled to
// LOCALEDIR/LANG/LC_MESSAGES/pupitre.mo). Every text a person reads goes
// through tr(); what programs read (--json, --trace, the diagnostic's shape,
// exit codes, numbers) never does. Adding a language is adding po/LANG.po.
// SPDX-License-Identifier: GPL-3.0-or-later
#pragma once
#include <string>
#include <string_view>

namespace pupitre {

// The text in the chosen language (the English msgid when none was chosen or
// the catalogue has no translation). xgettext keywords: tr, trn:1,2, N_.
const char* tr(const char* msgid) __attribute__((format_arg(1)));
// The form for n (ngettext): "%d warning" / "%d warnings".
const char* trn(const char* one, const char* many, unsigned long n)
    __attribute__((format_arg(1), format_arg(2)));
// Marks a text for the catalogue where it is stored (tables); translate with
// tr() where it is shown.
constexpr const char* N_(const char* msgid) {
    return msgid;
}
// printf into a std::string, positional arguments (%1$s) allowed, so that a
// translation may reorder them. Numbers always print with a decimal point:
// LC_NUMERIC stays "C" (i18n::init).
std::string strf(const char* fmt, ...) __attribute__((format(printf, 1, 2)));

namespace i18n {

// The messages locale the environment asks for, the GNU way: LC_ALL, then
// LC_MESSAGES, then LANG; LANGUAGE (a colon-separated list) wins over them
// unless that locale is C or POSIX. `get` reads a variable (nullptr: unset).
// Returns the candidate language codes in order of preference ("fr_FR.UTF-8"
// gives "fr_FR", then "fr").
using Getenv = const char* (*)(const char*);
std::string wanted(Getenv get);

// The language to use: `override` (--lang) when given, else the first of
// wanted()'s candidates that has a catalogue in `localedir` ("en" needs none),
// else "en". An unknown override is an error: returns "".
std::string choose(std::string_view override, const std::string& wanted_list,
                   const std::string& localedir);

// Sets the process up for `lang`: the locale from the environment for
// characters (falling back to C.UTF-8 where the named locale is not
// generated), LC_NUMERIC "C" always, and the catalogue from `localedir`.
void init(const std::string& lang, const std::string& localedir);

// English from here on, whatever init() chose: `run --json` carries the
// diagnostics' messages, and its output must not change with the language.
void use_english();

// The language chosen by init(): "en" by default.
std::string_view language();
// The languages with a catalogue in `localedir`, plus "en", sorted.
std::string available(const std::string& localedir);

}  // namespace i18n
}  // namespace pupitre
