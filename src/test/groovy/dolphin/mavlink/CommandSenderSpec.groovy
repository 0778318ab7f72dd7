package dolphin.mavlink

import com.MAVLink.common.msg_command_ack
import com.MAVLink.common.msg_command_long
import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_RESULT
import dolphin.core.ManualClock
import java.time.Duration
import spock.lang.Specification

/** Commands and their ACKs on a manual clock: the round trips they measure for the vehicle's link. */
class CommandSenderSpec extends Specification {

    ManualClock clock = new ManualClock()
    List<Integer> sent = []
    CommandSender sender = new CommandSender({ node, command -> sent << command.command } as CommandSender.Transmit,
            1_000_000_000L, 3)
    MAVLinkNode node = new MAVLinkNode('1', 'UAV', null, null, null, 1, 1, dolphin.mavlink.Autopilot.ARDUPILOT, VehicleFamily.COPTER, clock)

    private def ack(int command, int result) {
        new msg_command_ack(command: command, result: (short) result)
    }

    private long now() {
        clock.nanoTime()
    }

    def "an answer to a command sent once is a round-trip sample; one after a resend (Karn) or after IN_PROGRESS is not"() {
        when:
        def once = sender.submit(node, new msg_command_long(command: MAV_CMD.MAV_CMD_BATTERY_RESET), now())
        clock.advance(Duration.ofMillis(30))
        sender.onAck(node, ack(MAV_CMD.MAV_CMD_BATTERY_RESET, MAV_RESULT.MAV_RESULT_ACCEPTED), now())

        then:
        once.get().attempts() == 1
        node.roundTrip().samples() == 1
        node.roundTrip().smoothedNanos() == 30_000_000

        when: 'the first send is lost: the answer may be to either send'
        def resent = sender.submit(node, new msg_command_long(command: MAV_CMD.MAV_CMD_BATTERY_RESET), now())
        clock.advance(Duration.ofSeconds(1))
        sender.tick(now())
        clock.advance(Duration.ofMillis(20))
        sender.onAck(node, ack(MAV_CMD.MAV_CMD_BATTERY_RESET, MAV_RESULT.MAV_RESULT_ACCEPTED), now())

        then:
        resent.get().attempts() == 2
        sent.size() == 3
        node.roundTrip().samples() == 1

        when: 'IN_PROGRESS first: the final answer times the work, not the link'
        def slow = sender.submit(node, new msg_command_long(command: MAV_CMD.MAV_CMD_NAV_TAKEOFF), now())
        clock.advance(Duration.ofMillis(10))
        sender.onAck(node, ack(MAV_CMD.MAV_CMD_NAV_TAKEOFF, MAV_RESULT.MAV_RESULT_IN_PROGRESS), now())
        clock.advance(Duration.ofMillis(500))
        sender.onAck(node, ack(MAV_CMD.MAV_CMD_NAV_TAKEOFF, MAV_RESULT.MAV_RESULT_ACCEPTED), now())

        then:
        slow.get().result() == MAV_RESULT.MAV_RESULT_ACCEPTED
        node.roundTrip().samples() == 1
        node.roundTrip().smoothedNanos() == 30_000_000
    }
}
