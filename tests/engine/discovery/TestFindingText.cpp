// The findings' wording (issue #23): a cause turned down as `inconsistent` says by how much, in
// the parameter's unit, part by part, so that an engineer can weigh it (one batch with a trouble
// of its own, or a cause that is not the same everywhere).
#include "discovery/DiscoveryInternal.h"

#include <QtTest>

using namespace drytwin::discovery::detail;
using drytwin::discovery::PartEstimate;

class TestFindingText : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void inconsistentNamesThePooledValueAndEveryPart() {
        Consistency c;
        c.parts = {PartEstimate{"recording, part 1/3", 24.0, 5.0},
                   PartEstimate{"recording, part 2/3", 80.0, 6.0},
                   PartEstimate{"recording, part 3/3", 90.0, 7.5}};
        c.consistent = false;
        c.strays = 2;
        const std::string why = inconsistencyReason(c, Param::tau_meter, 63.0);
        qInfo("%s", why.c_str());
        QVERIFY2(why.find("strays from the pooled value (63 s) in 2 of 3 parts") != std::string::npos,
                 why.c_str());
        // Each part with its 95 % interval (1.96 standard errors), the unit once at the end.
        QVERIFY2(why.find("recording, part 1/3 24±9.8;") != std::string::npos, why.c_str());
        QVERIFY2(why.find("recording, part 2/3 80±12;") != std::string::npos, why.c_str());
        QVERIFY2(why.find("recording, part 3/3 90±15 s") != std::string::npos, why.c_str());
        QCOMPARE(why.substr(why.size() - 2), std::string(" s"));
    }

    void anOppositeSignIsSaidAsSuch() {
        Consistency c;
        c.parts = {PartEstimate{"B01", 0.4, 0.05}, PartEstimate{"B02", -0.3, 0.05}};
        c.consistent = false;
        c.opposite = true;
        c.strays = 1;
        const std::string why = inconsistencyReason(c, Param::X_in_offset, 0.05);
        QVERIFY2(why.find("opposite sign in part of the data (pooled 0.05 % wb)") != std::string::npos,
                 why.c_str());
        QVERIFY2(why.find("B02 -0.3±0.098 % wb") != std::string::npos, why.c_str());
    }

    /// Against a reference an output's response is judged by its direction; one that moved the
    /// other way by less than its noise can tell (a fouling's later compensation, seen on 2 x 1,500 s
    /// of heavy fouling) must not be told "the direction agrees".
    void anOutputMovedTheOtherWayIsNotSaidToAgree() {
        drytwin::discovery::Finding f;
        f.cause = "falling_rate_drying";
        f.parameter = Param::theta_fall;
        f.output = "T_out";
        f.responseJudged = true;
        f.actsOn = {true, true, false, false};
        f.responseScale = {-2.3, 2.3, 1.0, 1.0};
        const std::string text = findingEvidence(f, drytwin::discovery::DiscoveryOptions{});
        qInfo("%s", text.c_str());
        QVERIFY2(text.find("X_out moved against this cause's effect (-2.3 times what its model form says)") !=
                     std::string::npos,
                 text.c_str());
        QVERIFY2(text.find(
                     "T_out moved 2.3 times as much as this cause's model form says: the direction agrees") !=
                     std::string::npos,
                 text.c_str());
        QVERIFY2(text.find("X_out moved -2.3") == std::string::npos, text.c_str());
    }

    /// A part that hardly informs the estimate can step outside the parameter's range (a meter lag
    /// of -1,130 ± 650 s in one batch of a newcomer's data): the range said is held within it.
    void thePartsRangeIsHeldWithinTheParametersRange() {
        drytwin::discovery::Finding f;
        f.cause = "moisture_meter_lag";
        f.parameter = Param::tau_meter;
        f.output = "X_out";
        f.perPart = {PartEstimate{"B01", 172.0, 41.0}, PartEstimate{"B02", 169.0, 83.0},
                     PartEstimate{"B03", -1128.0, 649.0}};
        const std::string text = findingEvidence(f, drytwin::discovery::DiscoveryOptions{});
        QVERIFY2(
            text.find("Fitted part by part (3 parts) it lies between 0 and 172 s (a part whose estimate left "
                      "the parameter's range held at its bound).") != std::string::npos,
            text.c_str());
        f.perPart.pop_back();
        const std::string within = findingEvidence(f, drytwin::discovery::DiscoveryOptions{});
        QVERIFY2(within.find("it lies between 169 and 172 s.") != std::string::npos, within.c_str());
    }
};

QTEST_APPLESS_MAIN(TestFindingText)
#include "TestFindingText.moc"
