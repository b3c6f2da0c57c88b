// Results' JSON text and bytes that are not UTF-8 (docs/results-format.md): the UTF-8 check against
// RFC 3629's table of well-formed sequences; a document holding a Latin-1 string written with
// U+FFFD in its place and read back; a finished run whose name and case path are not UTF-8 keeps
// its summary.json; a case file whose name is not UTF-8 is refused at reading, naming the key.
#include "cosim/casefile/CaseFile.hpp"
#include "cosim/io/JsonText.hpp"
#include "cosim/run/CaseRun.hpp"
#include "SmallEngineCase.hpp"
#include "MinimalCaseFile.hpp"
#include "TestFiles.hpp"
#include "../TestScratch.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <string>

using namespace flexehd;
using namespace flexehd::cosim;

TEST(JsonText, TheUtf8CheckFollowsTheWellFormedSequences) {
    const std::size_t ok = std::string::npos;
    EXPECT_EQ(invalidUtf8At("plain ascii"), ok);
    EXPECT_EQ(invalidUtf8At("M\xC3\xBCller"), ok);                 // ü, two bytes
    EXPECT_EQ(invalidUtf8At("\xE2\x82\xAC 5"), ok);                 // €, three bytes
    EXPECT_EQ(invalidUtf8At("\xF0\x9F\x94\xA7"), ok);               // U+1F527, four bytes
    EXPECT_EQ(invalidUtf8At("M\xFCller"), 1u);                      // Latin-1 ü
    EXPECT_EQ(invalidUtf8At("ab\xC0\x80"), 2u);                     // overlong NUL
    EXPECT_EQ(invalidUtf8At("\xE0\x80\xAF"), 0u);                   // overlong '/'
    EXPECT_EQ(invalidUtf8At("\xED\xA0\x80"), 0u);                   // a surrogate, U+D800
    EXPECT_EQ(invalidUtf8At("\xF4\x90\x80\x80"), 0u);               // above U+10FFFF
    EXPECT_EQ(invalidUtf8At("x\xE2\x82"), 1u);                      // cut short
    EXPECT_EQ(invalidUtf8At("\x80"), 0u);                           // a lone continuation byte
}

TEST(JsonText, BytesThatAreNotUtf8AreWrittenAsTheReplacementCharacter) {
    const nlohmann::json doc{{"name", "M\xFCller"}, {"value", 1.5}};
    const std::string text = jsonText(doc, 2);
    const nlohmann::json back = nlohmann::json::parse(text);
    EXPECT_EQ(back.at("name").get<std::string>(), "M\xEF\xBF\xBDller");
    EXPECT_EQ(back.at("value").get<double>(), 1.5);
}

TEST(JsonText, AFinishedRunWhoseNameIsNotUtf8KeepsItsSummary) {
    const std::filesystem::path dir = test::scratchDir();
    EngineCase c = test::smallCase();
    c.name = "engine \xFC";
    c.path = (dir / "case_\xFC.yaml").string();
    c.time.maxCycles = 1;
    c.output.directory = (dir / "out").string();
    c.output.vtkEveryDeg = 0.0;
    runCase(c, {});
    std::ifstream s(dir / "out" / "summary.json");
    ASSERT_TRUE(s.good());
    const nlohmann::json d = nlohmann::json::parse(s);
    EXPECT_EQ(d.at("status").get<std::string>(), "ok");
    EXPECT_EQ(d.at("name").get<std::string>(), "engine \xEF\xBF\xBD");
}

TEST(JsonText, ACaseNameThatIsNotUtf8IsRefusedAtReading) {
    const std::filesystem::path dir = test::scratchDir();
    test::writeFile(dir / "p.csv", test::kMinimalPressureTable);
    test::writeFile(dir / "case.yaml", std::string(test::kMinimalCase) + "name: M\xFCller\n");
    const std::string error = test::errorOf([&] { readCaseFile((dir / "case.yaml").string()); });
    EXPECT_THAT(error, ::testing::AllOf(::testing::StartsWith((dir / "case.yaml").string() + ": name"),
                                        ::testing::HasSubstr("UTF-8"), ::testing::HasSubstr("0xFC at position 1")));
}
