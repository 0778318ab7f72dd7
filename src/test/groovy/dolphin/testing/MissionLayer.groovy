package dolphin.testing

import dolphin.mavlink.MAVLinkNode
import dolphin.mission.flight.MissionService
import dolphin.mission.flight.MissionTask
import dolphin.mission.model.Mission
import dolphin.mission.transfer.MissionDownloadProtocol
import dolphin.mission.transfer.MissionUploadProtocol

/** Specs' short ways to the mission layer of a vehicle and to the mission a script variable flies. */
final class MissionLayer {

    private MissionLayer() {
    }

    static MissionUploadProtocol uploads(MAVLinkNode node) {
        MissionService.of(node.communications()).vehicle(node).transfers().upload()
    }

    static MissionDownloadProtocol downloads(MAVLinkNode node) {
        MissionService.of(node.communications()).vehicle(node).transfers().download()
    }

    /** The mission of a task that {@code mission { }} or {@code missionFromFile} gave. */
    static Mission missionOf(Object task) {
        (task as MissionTask).mission()
    }
}
