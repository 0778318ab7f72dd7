package dolphin.mission.transfer

import com.MAVLink.enums.MAV_CMD
import dolphin.core.ManualClock
import dolphin.core.Position
import dolphin.mission.model.MissionItem
import java.time.Duration
import java.util.concurrent.CompletableFuture
import spock.lang.Specification
import spock.lang.Timeout
import spock.lang.Unroll

/**
 * Uploads and downloads of 100 items over a link that loses messages both ways at random (seeded),
 * to a vehicle that behaves as ArduPilot (LossyMissionVehicle: 50 to 70 ms each way, re-requests
 * after 1 s, cancels after 8 s without an item), on a manual clock with the default timeouts.
 */
@Timeout(120)
class LossyLinkTransferSpec extends Specification {

    static final Position HOME = Position.fromDegrees(41.15242, -8.64096, 72)

    ManualClock clock = new ManualClock()
    RecordingChannel channel = new RecordingChannel(clock)
    MissionTransfers transfers = new MissionTransfers(channel, new ClockTimers(clock),
            { new MissionTransferConfig(dolphin.mavlink.LinkTimeouts.DEFAULT, TransferPath.ITEMS) })

    def setup() {
        channel.transfers = transfers
    }

    /** Home, a takeoff and waypoints: {@code count} items, different each round. */
    static List<MissionItem> mission(int count, int round) {
        def items = [MissionItem.at(0, MAV_CMD.MAV_CMD_NAV_WAYPOINT, HOME, 0, 0, 0, 0),
                     MissionItem.at(1, MAV_CMD.MAV_CMD_NAV_TAKEOFF, HOME.displace(0, 0, 20 + round), 0, 0, 0, Float.NaN)]
        (2..<count).each { i -> items << MissionItem.at(i, MAV_CMD.MAV_CMD_NAV_WAYPOINT, HOME.displace(10 * i, 5 * round, 30), 0, 2, 0, Float.NaN) }
        items
    }

    /** Runs the clock until the transfer ends (at most 10 minutes); its clock time in seconds. */
    double runUntilDone(CompletableFuture<TransferResult> f) {
        long start = clock.nanoTime()
        long end = -1
        f.whenComplete { r, e -> end = clock.nanoTime() }
        while (end < 0 && clock.nanoTime() - start < 600_000_000_000L) {
            clock.advance(Duration.ofMillis(100))
        }
        assert f.done: 'the transfer has not ended after 10 minutes'
        (end - start) / 1e9
    }

    @Unroll
    def "#pct % loss both ways, 100 items: every upload completes and every download returns it, each upload within #bound s, #mean s on average"() {
        given:
        def vehicle = new LossyMissionVehicle(clock, channel, loss, seed)
        List<Double> ups = []
        List<Double> downs = []
        int resends = 0
        int ignored = 0
        int readBack = 0

        when:
        (1..uploads).each { round ->
            def items = mission(100, round)
            def up = transfers.upload().upload(items)
            ups << runUntilDone(up)
            def r = up.get()
            assert r.success(): r.error()
            assert vehicle.stored == items
            resends += r.resends()
            ignored += r.ignoredAcks()
            readBack += r.verified() ? 1 : 0
            def down = transfers.download().download()
            downs << runUntilDone(down)
            assert down.get().success(): down.get().error()
            assert MissionVerification.firstDifference(items, down.get().items()) == Optional.empty()
        }
        println String.format(Locale.ROOT, '%d%% loss, 100 items, %d uploads: upload mean %.1f s, max %.1f s; download mean %.1f s, '
                + 'max %.1f s; %d resends, %d INVALID_SEQUENCE, %d read back; vehicle cancelled %d; %s', pct, uploads,
                ups.sum() / ups.size(), ups.max(), downs.sum() / downs.size(), downs.max(), resends, ignored, readBack,
                vehicle.cancelled, channel.roundTrip)

        then:
        ups.every { it <= bound }
        ups.sum() / ups.size() <= mean
        vehicle.cancelled == 0

        where: // a lossless exchange takes one round trip (100 to 140 ms): 101 of them (COUNT and 100 items) 14.1 s. A
        // loss costs one timeout, the round trip and four deviations (about 150 ms), doubled if lost again, 600 ms at
        // most: at 10 % an exchange is lost one time in five, about 20 timeouts more, 3 s to 12 s; at 30 % one time in
        // two, about 100 more, 15 s to 60 s. An upload whose final ACK was lost then reads the list back: twice that.
        loss | seed | uploads || mean | bound
        0    | 1    | 3       || 14.1 | 14.1
        0.1  | 10   | 10      || 20   | 40
        0.3  | 30   | 10      || 75   | 150
        pct = (int) (loss * 100)
    }
}
