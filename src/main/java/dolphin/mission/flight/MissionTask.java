package dolphin.mission.flight;

import dolphin.core.NodeFilter;
import dolphin.core.PlatformTask;
import dolphin.core.PlatformTaskExecutor;
import dolphin.mission.model.Mission;
import java.util.List;

/**
 * A {@link Mission} as a Dolphin task, usable with every operator: each execution flies it on one
 * vehicle of any type with a new {@link MissionExecutor}. What {@code mission { }} and
 * {@code missionFromFile} give a script.
 */
public final class MissionTask extends PlatformTask {

    private final Mission mission;

    public MissionTask(Mission mission) {
        super(mission.getId());
        this.mission = mission;
    }

    public Mission mission() {
        return mission;
    }

    @Override
    public String kind() {
        return "mission";
    }

    /** One vehicle of any type. */
    @Override
    public List<NodeFilter> getRequirements() {
        return List.of(NodeFilter.ANY);
    }

    /** A new executor that uploads, starts and follows the mission on a MAVLink vehicle. */
    @Override
    public PlatformTaskExecutor getExecutor() {
        return new MissionExecutor(this, MissionService::vehicleOf);
    }
}
