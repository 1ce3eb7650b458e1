// The choice of language and the catalogue (issue 20).
// SPDX-License-Identifier: GPL-3.0-or-later
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>

#include "core/diag.hpp"
#include "core/i18n.hpp"

using namespace pupitre;

namespace {
std::map<std::string, std::string> g_env;
const char* fake_getenv(const char* name) {
    auto it = g_env.find(name);
    return it == g_env.end() ? nullptr : it->second.c_str();
}
std::string wanted(std::map<std::string, std::string> env) {
    g_env = std::move(env);
    return i18n::wanted(fake_getenv);
}
}  // namespace

TEST(I18n, WantedFollowsGnuOrder) {
    EXPECT_EQ(wanted({}), "");
    EXPECT_EQ(wanted({{"LANG", "fr_FR.UTF-8"}}), "fr_FR:fr");
    EXPECT_EQ(wanted({{"LANG", "fr_FR.UTF-8"}, {"LC_MESSAGES", "en_GB.UTF-8"}}), "en_GB:en");
    EXPECT_EQ(wanted({{"LANG", "en_US.UTF-8"}, {"LC_ALL", "fr_BE@euro"}}), "fr_BE:fr");
    // LANGUAGE wins over the locale, unless the locale is C or POSIX.
    EXPECT_EQ(wanted({{"LANG", "en_US.UTF-8"}, {"LANGUAGE", "fr:de"}}), "fr:de:en_US:en");
    EXPECT_EQ(wanted({{"LANG", "C"}, {"LANGUAGE", "fr"}}), "");
    EXPECT_EQ(wanted({{"LANGUAGE", "fr"}}), "");
    EXPECT_EQ(wanted({{"LC_ALL", "C.UTF-8"}, {"LANGUAGE", "fr"}}), "fr:C");
    EXPECT_EQ(wanted({{"LANG", ""}, {"LC_ALL", ""}}), "");
}

TEST(I18n, ChooseTakesTheFirstLanguageWithACatalogue) {
    auto dir =
        std::filesystem::temp_directory_path() / ("pupitre-i18n-" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir / "fr/LC_MESSAGES");
    std::ofstream(dir / "fr/LC_MESSAGES/pupitre.mo") << "";
    std::string d = dir.string();
    EXPECT_EQ(i18n::choose("", "", d), "en");
    EXPECT_EQ(i18n::choose("", "fr_FR:fr", d), "fr");
    EXPECT_EQ(i18n::choose("", "de_DE:de:fr", d), "fr");  // no German: the next one
    EXPECT_EQ(i18n::choose("", "en_GB:en:fr", d), "en");  // English asked before French
    EXPECT_EQ(i18n::choose("fr", "en_US:en", d), "fr");   // --lang wins
    EXPECT_EQ(i18n::choose("fr_CA.UTF-8", "", d), "fr");
    EXPECT_EQ(i18n::choose("en", "fr", d), "en");
    EXPECT_EQ(i18n::choose("de", "fr", d), "");  // unknown --lang: an error
    EXPECT_EQ(i18n::available(d), "en, fr");
    std::filesystem::remove_all(dir);
}

TEST(I18n, FrenchCatalogueAndDecimalPoint) {
    std::string dir = PUPITRE_LOCALE_BUILD_DIR;
    i18n::init("fr", dir);
    EXPECT_EQ(i18n::language(), "fr");
    EXPECT_STREQ(tr("The file is not text"), "Le fichier n'est pas du texte");
    // The NUM texts are the manual's French (data/errors.tsv).
    EXPECT_EQ(num_error_text(2),
              "Fonction G non reconnue, ou argument obligatoire absent derrière la fonction G");
    EXPECT_EQ(strf("%.3f", 1.5), "1.500");  // LC_NUMERIC stays C
    // A text with no translation is the English one.
    EXPECT_STREQ(tr("no such text in any catalogue"), "no such text in any catalogue");
    i18n::init("en", dir);
    EXPECT_STREQ(tr("The file is not text"), "The file is not text");
    EXPECT_EQ(num_error_text(2),
              "G code not recognised, or mandatory argument missing after the G code");
}
