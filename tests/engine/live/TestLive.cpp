// The live link's pieces that need no broker (engine/live/): the broker URL, the topic mapping,
// the payloads and the 1 s grid recorder. The broker end to end: tests/app/live/.
#include "live/BrokerUrl.h"
#include "live/GridRecorder.h"
#include "live/LiveMonitor.h"
#include "live/TagPayload.h"
#include "live/TopicMapping.h"

#include <QTemporaryDir>
#include <QtTest>
#include <cmath>
#include <fstream>
#include <random>
#include <sstream>

using namespace drytwin;
using namespace drytwin::live;
using data::Column;

namespace {

TagSample at(double timeS, double value) {
    return TagSample{timeS, true, value};
}

/// A batch of the six screen columns around fixed levels with independent noise, plus @p shift on
/// the outlet moisture from @p shiftFromS on.
data::Batch noisyBatch(const std::string& id, int rows, unsigned seed, double shift = 0,
                       double shiftFromS = 0) {
    std::mt19937 rng(seed);
    std::normal_distribution<double> noise(0.0, 1.0);
    data::Batch b;
    b.id = id;
    std::vector<double> time(static_cast<std::size_t>(rows));
    for (int r = 0; r < rows; ++r) {
        time[static_cast<std::size_t>(r)] = r;
    }
    b.setValues(Column::Time, time);
    const std::pair<Column, double> levels[] = {{Column::XOut, 12},    {Column::TOut, 55},
                                                {Column::THotSp, 160}, {Column::THot, 160},
                                                {Column::Feed, 6000},  {Column::XIn, 22}};
    for (const auto& [c, level] : levels) {
        std::vector<double> v(static_cast<std::size_t>(rows));
        for (int r = 0; r < rows; ++r) {
            v[static_cast<std::size_t>(r)] =
                level + 0.1 * noise(rng) + (c == Column::XOut && r >= shiftFromS ? shift : 0.0);
        }
        b.setValues(c, v);
    }
    b.lineOfRow.resize(static_cast<std::size_t>(rows));
    return b;
}

std::string fileText(const std::string& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

/// The rows of a batch file without its metadata lines.
std::string rowsOf(const std::string& path) {
    std::stringstream in(fileText(path)), out;
    for (std::string line; std::getline(in, line);) {
        if (line.rfind('#', 0) != 0) {
            out << line << '\n';
        }
    }
    return out.str();
}

} // namespace

class TestLive : public QObject {
    Q_OBJECT
private slots:
    void brokerUrls_data() {
        QTest::addColumn<QString>("url");
        QTest::addColumn<QString>("expected"); // text(), or the start of the error's reason
        QTest::newRow("plain") << "mqtt://127.0.0.1:1884"
                               << "mqtt://127.0.0.1:1884";
        QTest::newRow("default port") << "mqtt://broker.local"
                                      << "mqtt://broker.local:1883";
        QTest::newRow("tls default port") << "mqtts://broker.local"
                                          << "mqtts://broker.local:8883";
        QTest::newRow("ipv6") << "mqtt://[::1]:1900"
                              << "mqtt://[::1]:1900";
        QTest::newRow("scheme") << "tcp://host:1883"
                                << "a broker URL begins with";
        QTest::newRow("port text") << "mqtt://host:abc"
                                   << "the port 'abc' is not a number";
        QTest::newRow("port range") << "mqtt://host:70000"
                                    << "the port '70000' is not a number";
        QTest::newRow("no host") << "mqtt://:1883"
                                 << "no host name";
        QTest::newRow("user in url") << "mqtt://me:pw@host:1883"
                                     << "the URL holds only host and port";
    }
    void brokerUrls() {
        QFETCH(QString, url);
        QFETCH(QString, expected);
        const auto parsed = parseBrokerUrl(url.toStdString(), "--broker");
        if (parsed) {
            QCOMPARE(QString::fromStdString(parsed->text()), expected);
        } else {
            QCOMPARE(parsed.error().kind, ErrorKind::Usage);
            QVERIFY2(parsed.error().reason.rfind(expected.toStdString(), 0) == 0,
                     parsed.error().message().c_str());
            QVERIFY(parsed.error().place.find(url.toStdString()) != std::string::npos);
        }
    }

    void topicMappingDefaultsAndNames() {
        TopicMapping defaults;
        QCOMPARE(QString::fromStdString(defaults.topicOf(Column::XOut)), QString("drytwin/line1/X_out_pct"));
        QCOMPARE(QString::fromStdString(defaults.twinTopicPrefix()), QString("drytwin/line1/twin"));
        QCOMPARE(defaults.subscriptions().size(), std::size_t(13));
        auto mapped = readTopicMappingText(
            R"({"X_out_pct": "plant/NIR", "batch_id": "plant/B", "prefix": "tw"})", "t.json");
        QVERIFY(mapped);
        QCOMPARE(QString::fromStdString(mapped->topicOf(Column::XOut)), QString("plant/NIR"));
        QCOMPARE(QString::fromStdString(mapped->topicOf(Column::TOut)), QString("drytwin/line1/T_out_C"));
        QCOMPARE(QString::fromStdString(mapped->batchIdTopic()), QString("plant/B"));
        QCOMPARE(QString::fromStdString(mapped->twinTopicPrefix()), QString("tw"));
        QVERIFY(mapped->columnOf("plant/NIR") == Column::XOut);
        QVERIFY(!mapped->columnOf("drytwin/line1/X_out_pct"));
    }
    void topicMappingErrorsNamePlaceAndCause_data() {
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("message");
        QTest::newRow("not json") << "{\"X_out_pct\": }"
                                  << "t.json:1:15: the topic mapping is not valid JSON";
        QTest::newRow("unknown key") << "{\n  \"X_outlet\": \"a\"\n}"
                                     << "t.json:2:3: 'X_outlet' is not a measured";
        QTest::newRow("time") << "{\"time_s\": \"a\"}"
                              << "t.json:1:2: 'time_s' is not a measured";
        QTest::newRow("number") << "{\"X_out_pct\": 5}"
                                << "t.json:1:2: 'X_out_pct' must be a topic";
        QTest::newRow("wildcard") << "{\"X_out_pct\": \"plant/#\"}"
                                  << "t.json: X_out_pct: the topic 'plant/#' holds";
        QTest::newRow("shared") << "{\"X_out_pct\": \"a\", \"T_out_C\": \"a\"}"
                                << "t.json: 'T_out_C' and 'X_out_pct' are both";
    }
    void topicMappingErrorsNamePlaceAndCause() {
        QFETCH(QString, text);
        QFETCH(QString, message);
        const auto read = readTopicMappingText(text.toStdString(), "t.json");
        QVERIFY(!read);
        QCOMPARE(read.error().kind, ErrorKind::BadInput);
        QVERIFY2(read.error().message().rfind(message.toStdString(), 0) == 0, read.error().message().c_str());
    }

    void payloads() {
        auto r = readTagPayload(R"({"t": 1700000000, "v": 12.345})", 5);
        QVERIFY(r.ok && r.sample.stamped);
        QCOMPARE(r.sample.timeS, 1700000000.0);
        QCOMPARE(r.sample.value, 12.345);
        r = readTagPayload("23.5", 42);
        QVERIFY(r.ok && !r.sample.stamped);
        QCOMPARE(r.sample.timeS, 42.0);
        r = readTagPayload(R"({"t": "2023-11-14T22:13:20Z", "v": null})", 0);
        QVERIFY(r.ok && std::isnan(r.sample.value));
        QCOMPARE(r.sample.timeS, 1700000000.0);
        for (const char* bad : {"wet", R"({"t": 1, "v": "wet"})", R"({"t": "yesterday", "v": 1})",
                                R"({"t": 1})", "[1, 2]", "true", "", R"({"t": -5, "v": 1})", "{\"v\": 1"}) {
            const auto b = readTagPayload(bad, 0);
            QVERIFY2(!b.ok && !b.problem.empty(), bad);
        }
        // What the publisher writes reads back as the same doubles, NaN as null.
        for (double v : {0.1, 12.345, -3.0e-7, 1.0 / 3.0, 6497.5}) {
            const auto back = readTagPayload(formatTagPayload(1700000001.0, v), 0);
            QVERIFY(back.ok);
            QCOMPARE(back.sample.value, v);
            QCOMPARE(back.sample.timeS, 1700000001.0);
        }
        QVERIFY(std::isnan(readTagPayload(formatTagPayload(1.0, std::nan("")), 0).sample.value));
        std::string id, problem;
        double t = 0;
        QVERIFY(readBatchIdPayload(formatTextPayload(100, "B07"), 0, id, t, problem));
        QCOMPARE(QString::fromStdString(id), QString("B07"));
        QCOMPARE(t, 100.0);
        QVERIFY(!readBatchIdPayload(R"({"t": 1, "v": "../etc"})", 0, id, t, problem));
        QVERIFY(!readBatchIdPayload(R"({"v": 5})", 0, id, t, problem));
    }

    // In any order within the window, duplicates once, late ones counted, a gap left missing.
    void gridRecorderPlacesCountsAndMarksGaps() {
        QTemporaryDir dir;
        GridRecorderOptions o;
        o.folder = dir.path().toStdString();
        o.reorderWindowS = 3;
        o.sourceText = "test";
        GridRecorder rec(o);
        const double t0 = 1700000000;
        rec.addBatchStart("B01", t0);
        for (int s : {1, 0, 2, 3, 7, 8, 9, 10, 11, 12}) {          // 4, 5, 6 never come: a gap
            rec.addSample(Column::XOut, at(t0 + s + 0.2, 10 + s)); // 0.2 s off the grid: rounded
        }
        rec.addSample(Column::XOut, at(t0 + 2, 99)); // duplicate, still pending
        QVERIFY(rec.flush());
        rec.addSample(Column::XOut, at(t0 + 5, 99));  // late: its row is written
        rec.addSample(Column::XOut, at(t0 + 1, 99));  // duplicate of a written row
        rec.addSample(Column::TOut, at(t0 + 0, 40));  // late: a written row, another column
        rec.addSample(Column::TOut, at(t0 + 12, 41)); // still within the window
        rec.addMalformed();
        QVERIFY(rec.flush(true));
        const auto& c = rec.counts();
        QCOMPARE(c.samples, 11L);
        QCOMPARE(c.duplicates, 2L);
        QCOMPARE(c.late, 2L);
        QCOMPARE(c.malformed, 1L);
        QCOMPARE(c.rows, 13L);
        QCOMPARE(c.missingCells, 3L + 12L); // X_out 4-6; T_out everywhere but second 12
        QCOMPARE(rec.files().size(), std::size_t(1));
        std::string expected = "time_s,X_out_pct,T_out_C\n";
        for (int s = 0; s <= 12; ++s) {
            const bool gap = s >= 4 && s <= 6;
            expected += std::to_string(s) + "," + (gap ? "" : std::to_string(10 + s)) + "," +
                        (s == 12 ? "41" : "") + "\n";
        }
        QCOMPARE(QString::fromStdString(rowsOf(rec.files()[0])), QString::fromStdString(expected));
        QVERIFY(fileText(rec.files()[0])
                    .rfind("# batch: B01\n# source: test\n# start: 2023-11-14T22:13:20Z\n", 0) == 0);
    }

    void gridRecorderStartsFilesAtBatchIdsAndLongGaps() {
        QTemporaryDir dir;
        GridRecorderOptions o;
        o.folder = dir.path().toStdString();
        o.reorderWindowS = 0;
        o.splitGapS = 5;
        GridRecorder rec(o);
        const double t0 = 1700000000;
        rec.addBatchStart("A", t0);
        for (int s = 0; s < 4; ++s) {
            rec.addSample(Column::XOut, at(t0 + s, s));
        }
        rec.addBatchStart("B", t0 + 4);
        for (int s = 4; s < 8; ++s) {
            rec.addSample(Column::XOut, at(t0 + s, s));
        }
        for (int s = 20; s < 22; ++s) { // 12 s without a message: longer than the split gap
            rec.addSample(Column::XOut, at(t0 + s, s));
        }
        QVERIFY(rec.flush(true));
        QCOMPARE(rec.files().size(), std::size_t(3));
        QVERIFY(rec.files()[0].find("/A.csv") != std::string::npos);
        QVERIFY(rec.files()[1].find("/B.csv") != std::string::npos);
        QVERIFY(rec.files()[2].find("/live_20231114T221340.csv") != std::string::npos);
        QCOMPARE(QString::fromStdString(rowsOf(rec.files()[1])),
                 QString("time_s,X_out_pct\n0,4\n1,5\n2,6\n3,7\n"));
        QCOMPARE(rec.counts().missingCells, 0L);
        // A second recording into the same folder never overwrites the first.
        GridRecorder again(o);
        again.addBatchStart("A", t0);
        again.addSample(Column::XOut, at(t0, 1));
        QVERIFY(again.flush(true));
        QVERIFY(again.files()[0].find("/A_2.csv") != std::string::npos);
    }

    // The monitor fed row by row alarms after a shift, with an onset near it, and said once;
    // fed the same stream without the shift, it stays quiet.
    void monitorAlarmsOnceAfterAShift() {
        data::DataSet reference;
        for (unsigned r = 0; r < 3; ++r) {
            reference.batches.push_back(noisyBatch("R" + std::to_string(r), 1800, 100 + r));
        }
        auto commissioned = LiveMonitor::commission(reference, {});
        QVERIFY2(commissioned, commissioned ? "" : commissioned.error().message().c_str());
        QCOMPARE(commissioned->plannedRunS(), 1800.0);
        for (const double shift : {0.0, 0.3}) {
            LiveMonitor monitor = *commissioned;
            const data::Batch live = noisyBatch("L1", 1800, 7, shift, 600);
            std::vector<LiveAlarm> alarms;
            int windows = 0;
            std::array<double, data::kColumnCount> row{};
            for (std::size_t r = 0; r < live.rows(); ++r) {
                for (const auto c : LiveMonitor::columns()) {
                    row[static_cast<std::size_t>(c)] = (*live.values(c))[r];
                }
                auto out = monitor.push("L1", 1700000000, static_cast<double>(r), row);
                QVERIFY(out);
                for (const auto& w : *out) {
                    ++windows;
                    if (auto a = monitor.alarmOf(w)) {
                        alarms.push_back(*a);
                        QVERIFY(monitor.alarmPayload(*a, w).find("\"statistic\"") != std::string::npos);
                    }
                    QVERIFY(monitor.windowPayload(w).find("\"cusum_spe_limit\"") != std::string::npos);
                }
            }
            windows += static_cast<int>(monitor.finish().size());
            QCOMPARE(windows, 30);
            if (shift == 0) {
                QCOMPARE(alarms.size(), std::size_t(0));
            } else {
                QCOMPARE(alarms.size(), std::size_t(1));
                qInfo("shift 0.3 at 600 s: alarm by %s at %.0f s, onset %.0f s", alarms[0].statistic.c_str(),
                      alarms[0].timeS, alarms[0].onsetS);
                QVERIFY2(alarms[0].timeS > 600 && alarms[0].timeS <= 900,
                         std::to_string(alarms[0].timeS).c_str());
                QVERIFY(alarms[0].hasOnset);
                QVERIFY2(std::abs(alarms[0].onsetS - 600) <= 120, std::to_string(alarms[0].onsetS).c_str());
            }
        }
    }

    void monitorRefusesAReferenceWithoutItsColumns() {
        data::DataSet reference;
        reference.batches.push_back(noisyBatch("R0", 1800, 1));
        auto& b = reference.batches[0];
        b.numeric.erase(
            std::remove_if(b.numeric.begin(), b.numeric.end(),
                           [](const data::Batch::NumericColumn& c) { return c.id == Column::Feed; }),
            b.numeric.end());
        const auto commissioned = LiveMonitor::commission(reference, {});
        QVERIFY(!commissioned);
        QVERIFY2(commissioned.error().reason.find("lacks the column 'feed_kg_h'") != std::string::npos,
                 commissioned.error().message().c_str());
    }
};

QTEST_APPLESS_MAIN(TestLive)
#include "TestLive.moc"
