// The column-mapping guess on headers a user's historian writes (issue #72 item 6): the words
// of a tag say what its transmitter measures, before the values' range does.
#include "data/MappingGuess.h"

#include <QtTest>
#include <cmath>
#include <cstdio>
#include <string>

using namespace drytwin;
using namespace drytwin::data;

namespace {

/// A shift of one-second stamps with the headers given and one value per column; the inlet
/// moisture (22 % wb) lies where an inlet temperature could too (0–45 °C).
std::string shift(const std::string& header, const char* rowFormat) {
    std::string text = header + "\n";
    for (int i = 0; i < 600; ++i) {
        char line[256];
        std::snprintf(line, sizeof line, rowFormat, 8 + i / 3600, (i / 60) % 60, i % 60,
                      170 + 5 * std::sin(i / 300.0), 22 + 0.4 * std::sin(i / 500.0),
                      13 + 0.2 * std::sin(i / 400.0));
        text += line;
    }
    return text;
}

} // namespace

class TestMappingGuess : public QObject {
    Q_OBJECT
private Q_SLOTS:
    // "NIR_IN.PV" is an NIR moisture analyser at the inlet: the inlet moisture, never the inlet
    // material temperature, although its 22 fits both columns' ranges (before: T_in_C).
    void anNirAnalyserMeasuresMoisture() {
        const auto guess = guessMapping(shift("Timestamp,HDT_TEMP.PV,NIR_IN.PV,NIR_OUT.PV,FEED.PV",
                                              "2025-06-03 %02d:%02d:%02d,%.2f,%.2f,%.2f,6200\n"),
                                        "shift.csv");
        QVERIFY(guess.ok());
        const auto& m = guess->mapping.contractToFile;
        QVERIFY(m.count("X_in_pct"));
        QCOMPARE(m.at("X_in_pct"), std::string("NIR_IN.PV"));
        QVERIFY(!m.count("T_in_C") || m.at("T_in_C") != "NIR_IN.PV");
        QCOMPARE(m.at("X_out_pct"), std::string("NIR_OUT.PV"));
        QCOMPARE(m.at("T_hot_C"), std::string("HDT_TEMP.PV"));
        // Its reason names the header's words, which the dialog shows beside the choice.
        QVERIFY2(guess->reasons.at("X_in_pct").find("name") != std::string::npos,
                 guess->reasons.at("X_in_pct").c_str());
    }

    // A temperature at the inlet still goes to T_in_C: the moisture words take nothing from it.
    void anInletTemperatureStaysATemperature() {
        const auto guess = guessMapping(shift("Timestamp,HDT_TEMP.PV,FEED_TT202.PV,NIR_XOUT.PV,FEED.PV",
                                              "2025-06-03 %02d:%02d:%02d,%.2f,%.2f,%.2f,6200\n"),
                                        "shift.csv");
        QVERIFY(guess.ok());
        QCOMPARE(guess->mapping.contractToFile.at("T_in_C"), std::string("FEED_TT202.PV"));
        QVERIFY(!guess->mapping.contractToFile.count("X_in_pct"));
    }
};

QTEST_APPLESS_MAIN(TestMappingGuess)
#include "TestMappingGuess.moc"
