// Compensation's "does not improve" half (issue #23): a channel a cause acts on whose held-out
// error did not fall counts against the cause only where the channel could have shown the fall the
// cause's own effect predicts. Synthetic held-out errors with known effect sizes and serially
// correlated noise (as a line's error is), so the HAC standard error matters.
#include "discovery/DiscoveryInternal.h"

#include <QtTest>
#include <cmath>
#include <functional>
#include <random>

using namespace drytwin::discovery::detail;

namespace {

constexpr int kChannel = 1; // the outlet temperature's slot; any channel is judged alike

/// Three test batches of 2,000 rows each: AR(1) noise of rms @p noise (φ = 0.9) and @p removed
/// times a slow wave of rms 1 in "before" (the part of the cause's effect that is in the error);
/// "after" has the noise and @p added times the wave (what the fitted effect put there that the
/// line does not have).
std::pair<HeldOut, HeldOut> heldOutPair(double noise, double removed, double added, unsigned seed) {
    constexpr std::size_t rows = 2000;
    std::mt19937 rng(seed);
    std::normal_distribution<double> z(0, 1);
    HeldOut before, after;
    for (int b = 0; b < 3; ++b) {
        before.channels.emplace_back();
        after.channels.emplace_back();
        auto& e0 = before.channels.back()[kChannel].weightedError;
        auto& e1 = after.channels.back()[kChannel].weightedError;
        double ar = 0;
        for (std::size_t i = 0; i < rows; ++i) {
            ar = 0.9 * ar + std::sqrt(1 - 0.81) * z(rng);
            // The effect: a slow wave, as a sensor's lag leaves in the outlet temperature.
            const double wave = std::sqrt(2.0) * std::sin(2 * M_PI * static_cast<double>(i) / 400);
            e0.push_back(noise * ar + removed * wave);
            e1.push_back(noise * ar + added * wave);
        }
    }
    return {before, after};
}

/// Four batches of 3,000 s at 3 s, one channel, an offset's column (sensitivity 1 everywhere), and
/// as the error left at the pooled fit AR(1) noise of rms 0.05 (φ = 0.9) plus @p shape(t) [s].
Stack offsetStack(const std::function<double(double)>& shape, unsigned seed) {
    constexpr int batches = 4, rows = 1000;
    std::mt19937 rng(seed);
    std::normal_distribution<double> z(0, 1);
    Stack st;
    st.s = Eigen::MatrixXd::Ones(batches * rows, 1);
    st.r.resize(batches * rows);
    for (int b = 0; b < batches; ++b) {
        double ar = 0;
        for (int i = 0; i < rows; ++i) {
            ar = 0.9 * ar + std::sqrt(1 - 0.81) * z(rng);
            const double t = 3.0 * i;
            st.r(b * rows + i) = 0.05 * ar + shape(t);
            st.batch.push_back(b);
            st.row.push_back(i);
            st.channel.push_back(kChannel);
            st.timeS.push_back(t);
        }
    }
    return st;
}

} // namespace

class TestChannelJudgement : public QObject {
    Q_OBJECT
private Q_SLOTS:
    void changesCarryTheirStandardError() {
        const auto [before, after] = heldOutPair(1.0, 0.0, 0.0, 1);
        const auto ch = channelChanges(before, after)[kChannel];
        QVERIFY(ch.measured);
        QCOMPARE(ch.mseAfter, ch.mseBefore);         // nothing changed
        QCOMPARE(ch.changeSe, 0.0);                  // and the change has no spread
        QCOMPARE(unimprovedChannelP(ch, 0.25), 0.0); // no spread: the channel counts against it
        QVERIFY(!channelChanges(before, after)[0].measured);
    }

    /// Against a reference a channel is judged by the direction of the cause's effect: a model form
    /// that moves it three times as much as the line did still points the right way; one that
    /// moves it five times, the wrong way, or where the line did not move, does not.
    void againstAReferenceTheDirectionCountsNotTheSize() {
        std::array<bool, 4> actsOn{};
        actsOn[kChannel] = true;
        const auto judged = [&](double removed, double added) {
            const auto [before, after] = heldOutPair(0.3, removed, added, 7);
            return responseMismatch(before, after, actsOn);
        };
        // As the model says: the effect removes the line's change exactly (scale 1).
        auto r = judged(1.0, 0.0);
        QCOMPARE(r.channel, -1);
        QVERIFY2(std::abs(r.scale[kChannel] - 1) < 0.05, qPrintable(QString::number(r.scale[kChannel])));
        // The model's effect is three times the line's (it overshoots by twice the change): scale 1/3.
        r = judged(1.0, -2.0);
        QCOMPARE(r.channel, -1);
        QVERIFY2(std::abs(r.scale[kChannel] - 1.0 / 3) < 0.03,
                 qPrintable(QString::number(r.scale[kChannel])));
        QVERIFY(r.z[kChannel] > 0); // above the bound of 1/4
        // Five times the line's: beyond a factor of 4, not this cause's.
        QCOMPARE(judged(1.0, -4.0).channel, kChannel);
        // The wrong way: the fitted effect pushes the error further (scale -1).
        r = judged(1.0, 2.0);
        QCOMPARE(r.channel, kChannel);
        QVERIFY(r.scale[kChannel] < 0);
        // The line did not move on this channel at all, the effect does: scale about 0.
        QCOMPARE(judged(0.0, -0.5).channel, kChannel);
        // A miss under noise a hundred times the effect: the channel cannot judge the cause.
        {
            const auto [before, after] = heldOutPair(30.0, 0.0, -0.05, 8);
            QCOMPARE(responseMismatch(before, after, actsOn).channel, -1);
        }
        // A channel the cause does not act on is never held against it.
        actsOn[kChannel] = false;
        QCOMPARE(judged(1.0, 2.0).channel, -1);
    }

    void aLargeEffectThatMissesCountsAgainstTheCause() {
        // The fitted effect (rms 0.5 against an error of 1) is not in the data at all: it adds
        // itself to the error. The channel had every chance to show it.
        const auto [before, after] = heldOutPair(1.0, 0.0, 0.5, 2);
        const auto ch = channelChanges(before, after)[kChannel];
        QVERIFY(ch.mseAfter > ch.mseBefore);
        const double p = unimprovedChannelP(ch, 0.25);
        QVERIFY2(p < 1e-6, qPrintable(QString::number(p)));
    }

    void aSmallEffectUnderNoiseCannotBeJudged() {
        // The same miss with an effect of rms 0.05 under an error of rms 3 (a tenth of a kelvin
        // against the line's own error): the fall a right cause would bring (0.0025) is within
        // the change's noise, so this channel cannot judge the cause either way.
        const auto [before, after] = heldOutPair(3.0, 0.0, 0.05, 3);
        const auto ch = channelChanges(before, after)[kChannel];
        QVERIFY(ch.changeSe > 0);
        const double p = unimprovedChannelP(ch, 0.05 * 0.05);
        QVERIFY2(p > 0.05, qPrintable(QString::number(p)));
    }

    void aLookAlikeThatPredictsOneOutputBetterStaysInTheGroup() {
        // The named cause removes a large wave from the moisture (slot 0) and leaves a smaller one
        // in the temperature (slot 1) that its look-alike removes: overall the named cause is
        // better, on the temperature it is worse.
        auto [otherX, namedX] = heldOutPair(1.0, 3.0, 0.0, 7); // look-alike leaves 3, named 0
        auto [namedT, otherT] = heldOutPair(1.0, 1.0, 0.0, 8); // named leaves 1, look-alike 0
        HeldOut other = otherX, named = namedX;
        for (std::size_t b = 0; b < other.channels.size(); ++b) {
            other.channels[b][0] = otherX.channels[b][kChannel];
            named.channels[b][0] = namedX.channels[b][kChannel];
            other.channels[b][kChannel] = otherT.channels[b][kChannel];
            named.channels[b][kChannel] = namedT.channels[b][kChannel];
        }
        const std::array<bool, 4> both{true, true, false, false}, moistureOnly{true, false, false, false};
        QCOMPARE(QString::fromStdString(outputPredictedWorse(other, named, 0.05, both)),
                 QStringLiteral("T_out"));
        // Better on both: nothing held against it.
        QCOMPARE(QString::fromStdString(outputPredictedWorse(otherX, namedX, 0.05, both)), QString());
        // A named cause that does not act on the temperature (an outlet meter's offset) is not
        // held to it: the look-alike's gain there is not the same signature balanced otherwise.
        QCOMPARE(QString::fromStdString(outputPredictedWorse(other, named, 0.05, moistureOnly)), QString());
    }

    void aGaugeOffsetReadsTheSameEarlyAndLate() {
        // Fitted at 0.3: the error left is noise; both halves estimate 0.3 within their error.
        const auto c = constancyWithinBatch(offsetStack([](double) { return 0.0; }, 3), {}, 0, 0.3, 0);
        QVERIFY(c.checked);
        QVERIFY(c.constant);
        QVERIFY(std::abs(c.early.value - 0.3) < 3 * c.early.se);
        QVERIFY(std::abs(c.late.value - 0.3) < 3 * c.late.se);
        QVERIFY(c.early.se > 0 && c.late.se > 0);
    }

    void anErrorThatGrowsWithinTheBatchIsNotAnOffset() {
        // Fouling's growth, 1 − exp(−t / 3,000 s), fitted as an offset of 0.3: the first half
        // asks for less, the second for more.
        const auto growth = [](double t) { return 0.6 * (1 - std::exp(-t / 3000)) - 0.3; };
        const auto c = constancyWithinBatch(offsetStack(growth, 4), {}, 0, 0.3, 0);
        QVERIFY(c.checked);
        QVERIFY(!c.constant);
        QVERIFY(c.late.value > c.early.value + 0.15);
        // Its mean over each half, added to the pooled 0.3 (within 0.02 of the noise).
        QVERIFY(std::abs(c.early.value - (0.3 + 0.6 * (1 - 3000.0 / 1500 * (1 - std::exp(-0.5))) - 0.3)) <
                0.02);
    }

    void anOffsetFromItsOnsetIsJudgedFromItsOnset() {
        // A step of 0.4 at 1,500 s into each batch, fitted from its onset: the error left after it
        // is noise, so from the onset on it is constant; judged from the batch start (no onset
        // found yet) the first half sees none of it, which is what sends discovery to look for an
        // onset (CandidateFits.cpp).
        const auto fromOnset =
            constancyWithinBatch(offsetStack([](double) { return 0.0; }, 5), {}, 0, 0.4, 1500);
        QVERIFY(fromOnset.checked);
        QVERIFY(fromOnset.constant);
        const auto step = [](double t) { return t < 1500 ? -0.2 : 0.2; }; // an offset of 0.2 pooled
        const auto fromStart = constancyWithinBatch(offsetStack(step, 5), {}, 0, 0.2, 0);
        QVERIFY(!fromStart.constant);
        QVERIFY(std::abs(fromStart.early.value) < 0.05);
        QVERIFY(std::abs(fromStart.late.value - 0.4) < 0.05);
    }

    void theRightCauseMeetsItsPrediction() {
        // A cause right on the channel removes its own effect: the change is what it predicts,
        // within its noise, and a shortfall is not significant.
        const auto [before, after] = heldOutPair(1.0, 0.5, 0.0, 4);
        const auto ch = channelChanges(before, after)[kChannel];
        QVERIFY(ch.mseAfter < ch.mseBefore);
        QVERIFY(std::abs((ch.mseBefore - ch.mseAfter) - 0.25) < 3 * ch.changeSe);
        const double p = unimprovedChannelP(ch, 0.25);
        QVERIFY2(p > 0.01, qPrintable(QString::number(p)));
    }

    // A new period on a hot day against a reference of cooler days: the judgement says the
    // conditions were never seen, for that batch and that input only.
    void aConditionTheReferenceNeverSawIsNamed() {
        const auto batchAt = [](const std::string& id, double ambientC, double rows) {
            drytwin::data::SiBatch b;
            b.id = id;
            for (int k = 0; k < rows; ++k) {
                b.timeS.push_back(k);
                b.tHotK.push_back(423.15 + std::sin(0.01 * k));
                b.airSpeedMPerS.push_back(16);
                b.feedKgPerS.push_back(6200.0 / 3600);
                b.xInDb.push_back(0.28);
                b.tInK.push_back(298.15);
                b.tAmbK.push_back(273.15 + ambientC + 0.5 * std::sin(0.003 * k));
                b.rhAmb.push_back(0.5);
                b.keep.push_back(1);
            }
            return b;
        };
        const std::vector<drytwin::data::SiBatch> reference{batchAt("R1", 12, 600), batchAt("R2", 22, 600)};
        const auto notes = operatingRangeNotes(reference, {batchAt("N1", 18, 300), batchAt("N2", 31.7, 300)});
        QCOMPARE(notes.size(), std::size_t(1));
        QVERIFY2(notes.front().rfind("N2: T_amb_C is typically 31.", 0) == 0 &&
                     notes.front().find("outside what the reference saw (12.0") != std::string::npos,
                 notes.front().c_str());
        QVERIFY(operatingRangeNotes(reference, {batchAt("N3", 24, 300)}).empty()); // within the margin
        // Cold and dry: one note for the batch, both inputs in it.
        auto coldDry = batchAt("N4", 2, 300);
        std::fill(coldDry.rhAmb.begin(), coldDry.rhAmb.end(), 0.05);
        const auto both = operatingRangeNotes(reference, {coldDry});
        QCOMPARE(both.size(), std::size_t(1));
        QVERIFY2(both.front().rfind("N4: ", 0) == 0 &&
                     both.front().find("T_amb_C is typically 2") != std::string::npos &&
                     both.front().find("; RH_amb_pct is typically 5 %") != std::string::npos,
                 both.front().c_str());
    }

    /// Against a reference, once a change is detected, a cause's share is also counted of the
    /// change: the held-out error beyond the reference's own level, not of the noise both have.
    void aCauseIsMeasuredAgainstTheChangeOnceOneIsDetected() {
        const auto heldWith = [](double perRow) {
            HeldOut h;
            h.loss = {std::vector<double>(100, perRow)};
            return h;
        };
        Reference ref;
        ref.normalHeldLoss = 0.027;
        Problem pr;
        pr.reference = &ref;
        const HeldOut before = heldWith(0.035), after = heldWith(0.030);
        QCOMPARE(shareOfChange(pr, before, after), 0.0); // nothing detected yet
        ref.changeDetected = true;
        // (0.035 - 0.030) / (0.035 - 0.027): 62 % of the change, 14 % of the whole error.
        QVERIFY(std::abs(shareOfChange(pr, before, after) - 0.625) < 1e-9);
        pr.options.shareOfChangeOnceDetected = false; // the rule before
        QCOMPARE(shareOfChange(pr, before, after), 0.0);
        pr.options.shareOfChangeOnceDetected = true;
        ref.normalHeldLoss = 0.033; // an excess under a tenth of the normal level is noise
        QCOMPARE(shareOfChange(pr, before, after), 0.0);
        ref.normalHeldLoss = 0.027;
        QCOMPARE(shareOfChange(pr, before, heldWith(0.020)), 1.0); // at most all of it
        Problem alone;                                             // one data set alone: the whole error only
        QCOMPARE(shareOfChange(alone, before, after), 0.0);
    }

    /// The outlet temperature answers 18 s later than the model, the moisture 3 s (under a meter's
    /// normal response). Alone that is the line's own thermal dynamics. Against a reference, whose
    /// structure holds the line's own answer, it turns a transport time down only where the
    /// moisture contradicts the temperature's delay (its held-out error worse at 18 s than at its
    /// own 3 s); a meter lag, which delays the moisture alone, is turned down either way.
    void againstAReferenceALaterTemperatureIsTheLinesOnlyWhereTheMoistureContradictsIt() {
        // The held-out errors at each channel's own delay: the moisture's the same at both
        // (it does not pin its delay down) or 30 % larger in rms at the temperature's.
        const auto held = [](double moistureScale, double temperatureScale) {
            std::mt19937 rng(5);
            std::normal_distribution<double> z(0, 1);
            HeldOut h;
            for (int b = 0; b < 3; ++b) {
                h.channels.emplace_back();
                double ar = 0;
                for (int i = 0; i < 2000; ++i) {
                    ar = 0.5 * ar + z(rng);
                    h.channels.back()[kXOut].weightedError.push_back(moistureScale * ar);
                    h.channels.back()[kTOut].weightedError.push_back(temperatureScale * ar);
                }
            }
            return h;
        };
        const HeldOut atMoistureDelay = held(1.0, 1.5);
        const HeldOut atTemperatureDelay = held(1.0, 1.0);      // the moisture no worse at 18 s
        const HeldOut atTemperatureDelayWorse = held(1.3, 1.0); // the moisture worse at 18 s
        Problem alone;
        const ChannelTiming aloneTiming = channelTiming(alone, 0, 3, 18, atMoistureDelay, atTemperatureDelay);
        QVERIFY(aloneTiming.pattern == ChannelTiming::Pattern::TemperatureOnly);
        QVERIFY(!transportSparedByMoisture(alone, aloneTiming)); // alone: the line's dynamics
        Reference ref;
        Problem against;
        against.reference = &ref;
        const ChannelTiming consistent =
            channelTiming(against, 0, 3, 18, atMoistureDelay, atTemperatureDelay);
        QVERIFY(consistent.pattern ==
                ChannelTiming::Pattern::TemperatureOnly); // a meter lag still turned down
        QVERIFY(consistent.moistureWorseAtTemperatureDelayP > 0.05);
        QVERIFY(transportSparedByMoisture(against, consistent)); // the transport time stays a candidate
        const ChannelTiming contradicted =
            channelTiming(against, 0, 3, 18, atMoistureDelay, atTemperatureDelayWorse);
        QVERIFY(contradicted.moistureWorseAtTemperatureDelayP < 1e-6);
        QVERIFY(!transportSparedByMoisture(against, contradicted));
    }

    /// A fitted cause's normal spread: at its upper 75 % bound until a detector has flagged a
    /// change (it keeps the causes' change test at its false-alarm rate), at its point estimate
    /// once one has (naming then asks which cause moved).
    void theNormalSpreadIsItsPointEstimateOnceAChangeIsDetected() {
        Reference ref;
        ref.fitted = [](Param) -> drytwin::Expected<ReferenceValue> {
            ReferenceValue rv;
            rv.value = 0.2;
            rv.se = 0.01;
            rv.spread = 0.3;       // bound
            rv.spreadPoint = 0.12; // point estimate
            return rv;
        };
        Problem pr;
        pr.reference = &ref;
        drytwin::discovery::Finding f;
        f.parameter = Param::theta_reabs;
        f.value = 0.55; // 0.35 above the normal value: beyond 1.96 × 0.12, within 1.96 × 0.3
        f.ci95Low = 0.53;
        f.ci95High = 0.57;
        auto within = judgeAgainstReference(pr, f);
        QVERIFY(within.ok());
        QVERIFY2(within->find("within its normal spread") == 0, within->c_str());
        ref.changeDetected = true;
        auto moved = judgeAgainstReference(pr, f);
        QVERIFY(moved.ok());
        QVERIFY2(moved->empty(), moved->c_str());
        pr.options.pointSpreadOnceDetected = false; // the rule before
        auto bound = judgeAgainstReference(pr, f);
        QVERIFY(bound.ok() && !bound->empty());
    }

    // A meter's lag acts on the outlet moisture alone: the share it must remove is also counted on
    // that channel, where the tube outlet's error (which it cannot touch) does not dilute it. Here
    // the cause removes 40 % of X_out's squared error and nothing of a tube-outlet channel three
    // times as large: 10 % of the whole, 40 % of its own channel.
    void aDownstreamCauseIsJudgedOnTheChannelsItActsOn() {
        constexpr std::size_t rows = 1200;
        std::mt19937 rng(7);
        std::normal_distribution<double> z(0, 1);
        HeldOut before, after;
        for (int b = 0; b < 2; ++b) {
            before.channels.emplace_back();
            after.channels.emplace_back();
            before.loss.emplace_back();
            after.loss.emplace_back();
            for (std::size_t i = 0; i < rows; ++i) {
                const double t = 3.0 * static_cast<double>(i);
                const double noise = z(rng), tube = z(rng);
                // X_out: the lag's part (a fast wave of rms sqrt(0.4)) and noise of rms sqrt(0.6);
                // T_hdt: three times X_out's squared error, untouched.
                const double lagPart = std::sqrt(0.4) * std::sqrt(2.0) * std::sin(2 * M_PI * t / 90);
                const double x0 = lagPart + std::sqrt(0.6) * noise, x1 = std::sqrt(0.6) * noise;
                const double hdt = std::sqrt(3.0) * tube;
                for (auto* h : {&before, &after}) {
                    for (int c = 0; c < 4; ++c) {
                        h->channels.back()[static_cast<std::size_t>(c)].timeS.push_back(t);
                    }
                    h->channels.back()[kXOut].weightedError.push_back(h == &before ? x0 : x1);
                    h->channels.back()[kTOut].weightedError.push_back(0.0);
                    h->channels.back()[kXHdt].weightedError.push_back(0.0);
                    h->channels.back()[kTHdt].weightedError.push_back(hdt);
                    h->loss.back().push_back((h == &before ? x0 * x0 : x1 * x1) + hdt * hdt);
                }
            }
        }
        drytwin::discovery::DiscoveryOptions options;
        const auto [whole, fast] = explainedShares(before, after, options);
        QVERIFY2(whole > 0.07 && whole < 0.13, qPrintable(QString::number(whole)));
        QVERIFY2(fast < 0.15, qPrintable(QString::number(fast)));
        const auto meter = outletChannelsActedOn(drytwin::properties::Param::tau_meter);
        QVERIFY(meter.has_value());
        QVERIFY((*meter)[kXOut] && !(*meter)[kTOut] && !(*meter)[kXHdt] && !(*meter)[kTHdt]);
        const auto [onX, onXFast] = explainedSharesOnChannels(before, after, *meter, options);
        QVERIFY2(onX > 0.35 && onX < 0.45, qPrintable(QString::number(onX)));
        QVERIFY2(onXFast > 0.35, qPrintable(QString::number(onXFast)));
        // The transport time acts on both outlet channels; a cause in the tube on every channel.
        const auto transport = outletChannelsActedOn(drytwin::properties::Param::dtau_conv);
        QVERIFY(transport && (*transport)[kXOut] && (*transport)[kTOut] && !(*transport)[kTHdt]);
        QVERIFY(!outletChannelsActedOn(drytwin::properties::Param::theta_foul).has_value());
        QCOMPARE(outletChannelsName(*meter), std::string("the outlet moisture's"));
        // Over every channel the same function gives back the overall shares.
        const auto [allWhole, allFast] =
            explainedSharesOnChannels(before, after, {true, true, true, true}, options);
        QVERIFY(std::abs(allWhole - whole) < 1e-12);
        QVERIFY(std::abs(allFast - fast) < 1e-12);
    }
};

QTEST_APPLESS_MAIN(TestChannelJudgement)
#include "TestChannelJudgement.moc"
