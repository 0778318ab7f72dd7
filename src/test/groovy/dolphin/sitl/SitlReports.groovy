package dolphin.sitl

import com.MAVLink.Messages.MAVLinkMessage
import com.MAVLink.common.msg_mission_item_reached
import com.MAVLink.minimal.msg_heartbeat
import com.MAVLink.standard.msg_global_position_int
import dolphin.mavlink.MAVLinkCommunications
import dolphin.mavlink.MAVLinkNode
import java.util.concurrent.ConcurrentHashMap

/**
 * What each SITL vehicle reported during a run, by system id, from its autopilot's messages as our
 * ground station decoded them: the MAVLink types in its heartbeats, the items it reported reached
 * (MISSION_ITEM_REACHED) and the lowest height relative to home it reported (GLOBAL_POSITION_INT,
 * metres; a sub's depth is a negative one) once it had a position: before, ArduPilot sends latitude
 * and longitude 0 and a height that means nothing (−0.4 m from a sub at the surface). The node's
 * own state keeps only the last of each.
 */
class SitlReports implements MAVLinkCommunications.ComponentListener {

    private static final int AUTOPILOT = 1

    final Map<Integer, Set<Integer>> heartbeatTypes = new ConcurrentHashMap<>()
    final Map<Integer, Set<Integer>> itemsReached = new ConcurrentHashMap<>()
    final Map<Integer, Double> lowestRelativeAlt = new ConcurrentHashMap<>()

    static SitlReports listeningTo(MAVLinkCommunications comms) {
        def reports = new SitlReports()
        comms.addComponentListener(reports)
        reports
    }

    @Override
    void message(MAVLinkNode node, int component, MAVLinkMessage message) {
        if (component != AUTOPILOT) {
            return
        }
        int sysid = node.mavLinkId
        if (message instanceof msg_heartbeat) {
            add(heartbeatTypes, sysid, message.type)
        } else if (message instanceof msg_mission_item_reached) {
            add(itemsReached, sysid, message.seq)
        } else if (message instanceof msg_global_position_int && (message.lat != 0 || message.lon != 0)) {
            lowestRelativeAlt.merge(sysid, message.relative_alt / 1000d, Math::min)
        }
    }

    private static void add(Map<Integer, Set<Integer>> sets, int sysid, int value) {
        sets.computeIfAbsent(sysid) { ConcurrentHashMap.newKeySet() } << value
    }
}
