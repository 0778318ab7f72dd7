package dolphin.mission.file

import com.MAVLink.enums.MAV_CMD
import com.MAVLink.enums.MAV_FRAME
import dolphin.core.Position
import dolphin.mission.model.Mission
import dolphin.mission.model.MissionItem
import dolphin.mission.model.TakeOffPoint
import dolphin.mission.survey.Cameras
import dolphin.mission.survey.CorridorScan
import dolphin.mission.survey.EntryCorner
import dolphin.mission.survey.HeightReference
import dolphin.mission.survey.MappingItem
import dolphin.mission.survey.PhotoGrid
import dolphin.mission.survey.PolygonSurvey
import dolphin.mission.survey.StructureScan
import dolphin.mission.survey.TransectOptions
import groovy.json.JsonOutput
import groovy.json.JsonSlurper
import spock.lang.Specification

/** Surveys, corridor scans and structure scans in QGroundControl plans: written editable, read back, regenerated. */
class PlanComplexItemsSpec extends Specification {

    static final Position HOME = Position.fromDegrees(40.444233, -7.375234, 820)
    static final List<Position> FIELD = [[40.4450, -7.3760], [40.4470, -7.3760], [40.4470, -7.3725], [40.4450, -7.3725]]
            .collect { Position.fromDegrees(it[0], it[1], 0) }
    static final List<Position> ROAD = [[40.4450, -7.3760], [40.4480, -7.3740], [40.4485, -7.3700]]
            .collect { Position.fromDegrees(it[0], it[1], 0) }

    static PolygonSurvey manualSurvey(TransectOptions options = TransectOptions.defaults()) {
        new PolygonSurvey('survey', FIELD, PhotoGrid.manual(50, 25, 20), 30, EntryCorner.TOP_LEFT, false, options)
    }

    static PolygonSurvey cameraSurvey() {
        new PolygonSurvey('survey', FIELD, PhotoGrid.atAltitude(Cameras.named('GoPro Hero 4').get(), true, 100, 80, 70),
                0, EntryCorner.BOTTOM_RIGHT, true, TransectOptions.defaults())
    }

    static CorridorScan corridor() {
        new CorridorScan('corridor', ROAD, 40, PhotoGrid.manual(50, 20, 25), EntryCorner.TOP_RIGHT, TransectOptions.defaults())
    }

    static StructureScan structure() {
        new StructureScan('structureScan', FIELD, PhotoGrid.manual(20, 25, 5), 40, 10, 50, true, 0)
    }

    /** Take-off, the mapping item, then a waypoint: the mission and its file. */
    static MissionFile file(MappingItem m) {
        Mission mission = new Mission('survey', HOME, [new TakeOffPoint('takeOff', HOME.atHeight(850), 0, Float.NaN), m,
                                                       new dolphin.mission.model.GoToPoint(HOME.atHeight(870))])
        MissionFile.of(mission, mission.items(null))
    }

    static Map json(String text) {
        new JsonSlurper().parseText(text) as Map
    }

    def "#kind is written as QGroundControl's ComplexItem and reads back as the same items"() {
        given:
        MissionFile f = file(m)
        int n = m.items(2).size()

        when:
        String text = PlanFile.write(f)
        Map item = json(text).mission.items[1]

        then:
        json(text).mission.items*.type == ['SimpleItem', 'ComplexItem', 'SimpleItem']
        item.complexItemType == m.qgcType()
        item.version == version
        json(text).mission.items[2].doJumpId == 2 + n

        and: 'the items come back equal, stored or regenerated'
        PlanFile.read(text) == f.mission()

        where:
        kind               | m               | version
        'a survey'         | manualSurvey()  | 5
        'a camera survey'  | cameraSurvey()  | 5
        'a corridor scan'  | corridor()      | 2
        'a structure scan' | structure()     | 3
    }

    def "a survey's keys are those of docs/qgc-surveys.md §4, its items SimpleItems numbered from its seq"() {
        given:
        PolygonSurvey s = manualSurvey()

        when:
        Map item = json(PlanFile.write(file(s))).mission.items[1]
        Map ts = item.TransectStyleComplexItem

        then:
        item.keySet() == ['type', 'complexItemType', 'version', 'polygon', 'angle', 'entryLocation', 'flyAlternateTransects',
                          'splitConcavePolygons', 'TransectStyleComplexItem'] as Set
        item.polygon.size() == 4
        item.angle == 30
        item.entryLocation == 0
        ts.version == 2
        ts.TurnAroundDistance == 10
        ts.CameraTriggerInTurnAround == true
        ts.CameraShots == s.coverage().photos()
        ts.CameraCalc == [version: 2, CameraName: 'Manual (no camera specs)', DistanceToSurface: 50, DistanceMode: 1,
                          AdjustedFootprintSide: 25, AdjustedFootprintFrontal: 20]
        ts.VisualTransectPoints.size() == s.path().size()
        ts.Items.size() == s.items(2).size()
        ts.Items*.doJumpId == (2..<(2 + s.items(2).size())).toList()
        ts.Items.every { it.type == 'SimpleItem' }
    }

    def "a camera's numbers are written and kept on reading"() {
        when:
        Map calc = json(PlanFile.write(file(cameraSurvey()))).mission.items[1].TransectStyleComplexItem.CameraCalc

        then:
        calc.CameraName == 'GoPro Hero 4'
        calc.SensorWidth == 6.17
        calc.ImageWidth == 4000
        calc.FocalLength == 2.98
        calc.Landscape == true
        calc.FrontalOverlap == 80
        calc.SideOverlap == 70
        calc.ValueSetIsDistance == true
    }

    /** The plan of {@code m} with its stored items (and visual points) taken out, as a hand-made plan has none. */
    static String withoutItems(MappingItem m, Closure edit = {}) {
        Map plan = json(PlanFile.write(file(m)))
        Map item = plan.mission.items[1]
        item.TransectStyleComplexItem?.remove('Items')
        item.TransectStyleComplexItem?.remove('VisualTransectPoints')
        edit(item)
        JsonOutput.toJson(plan)
    }

    def "#kind without stored items is regenerated from its settings"() {
        expect:
        PlanFile.read(withoutItems(m)) == file(m).mission()

        where:
        kind              | m
        'a survey'        | manualSurvey()
        'a camera survey' | cameraSurvey()
        'a corridor scan' | corridor()
    }

    def "stored items win over the settings: they are what QGroundControl uploads"() {
        given:
        Map plan = json(PlanFile.write(file(manualSurvey())))
        List stored = plan.mission.items[1].TransectStyleComplexItem.Items
        stored[0].params[6] = 77

        expect:
        PlanFile.read(JsonOutput.toJson(plan))[2].z() == 77f
    }

    def "the distance mode gives the frame; calculated above terrain is flown in the terrain frame"() {
        when:
        List<MissionItem> items = PlanFile.read(withoutItems(manualSurvey()) { Map item ->
            item.TransectStyleComplexItem.CameraCalc.DistanceMode = mode
        })

        then:
        items.findAll { it.command() == MAV_CMD.MAV_CMD_NAV_WAYPOINT && it.seq() in 2..<items.size() - 1 }*.frame().unique() == [frame]

        where:
        mode | frame
        1    | MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT
        2    | MAV_FRAME.MAV_FRAME_GLOBAL_INT
        3    | MAV_FRAME.MAV_FRAME_GLOBAL_TERRAIN_ALT_INT
        4    | MAV_FRAME.MAV_FRAME_GLOBAL_TERRAIN_ALT_INT
    }

    def "version 1 keys: DistanceToSurfaceRelative and FollowTerrain"() {
        when:
        List<MissionItem> items = PlanFile.read(withoutItems(manualSurvey()) { Map item ->
            Map calc = item.TransectStyleComplexItem.CameraCalc
            calc.version = 1
            calc.remove('DistanceMode')
            calc.DistanceToSurfaceRelative = relative
            item.TransectStyleComplexItem.version = 1
            item.TransectStyleComplexItem.FollowTerrain = follow
            item.version = 4
        })

        then:
        items[2].frame() == frame

        where:
        relative | follow | frame
        true     | false  | MAV_FRAME.MAV_FRAME_GLOBAL_RELATIVE_ALT_INT
        false    | false  | MAV_FRAME.MAV_FRAME_GLOBAL_INT
        true     | true   | MAV_FRAME.MAV_FRAME_GLOBAL_TERRAIN_ALT_INT
    }

    def "a structure scan has no stored items, as QGroundControl saves it: (N + 3) L + 4 regenerated"() {
        given:
        StructureScan s = structure()

        when:
        Map item = json(PlanFile.write(file(s))).mission.items[1]

        then:
        item.keySet() == ['type', 'complexItemType', 'version', 'polygon', 'StructureHeight', 'ScanBottomAlt', 'Layers',
                          'StartFromTop', 'EntranceAltitude', 'GimbalPitch', 'CameraCalc'] as Set
        item.Layers == s.layers()
        PlanFile.read(PlanFile.write(file(s))).size() == 1 + 1 + (FIELD.size() + 3) * s.layers() + 4 + 1
    }

    def "a missing or wrong key is named by its JSON path"() {
        when:
        PlanFile.read(withoutItems(m, edit))

        then:
        IllegalArgumentException e = thrown()
        e.message == message

        where:
        m              | edit                                                                          | message
        manualSurvey() | { it.remove('angle') }                                                        | 'mission.items[1].angle: expected a number, found nothing'
        manualSurvey() | { it.entryLocation = 7 }                                                      | 'mission.items[1].entryLocation: expected 0 to 3 (top left, top right, bottom left, bottom right), found 7'
        manualSurvey() | { it.TransectStyleComplexItem.CameraCalc.DistanceMode = 0 }                   | 'mission.items[1].TransectStyleComplexItem.CameraCalc.DistanceMode: a QGroundControl distance mode is 1 (relative), 2 (absolute), 3 (calculated above terrain) or 4 (terrain frame), got 0'
        manualSurvey() | { it.TransectStyleComplexItem.remove('HoverAndCapture') }                     | 'mission.items[1].TransectStyleComplexItem.HoverAndCapture: expected true or false, found nothing'
        manualSurvey() | { it.polygon[1] = [95, 1] }                                                   | 'mission.items[1].polygon[1][0] (latitude): 95 is out of range for a latitude (-90 to 90)'
        manualSurvey() | { it.version = 3 }                                                            | 'mission.items[1].version: a survey of version 3 without expanded items cannot be regenerated (versions 4 to 5 can); open and save the plan in QGroundControl to store its items'
        corridor()     | { it.remove('CorridorWidth') }                                                | 'mission.items[1].CorridorWidth: expected a number, found nothing'
        structure()    | { it.CameraCalc.remove('AdjustedFootprintFrontal') }                          | 'mission.items[1].CameraCalc.AdjustedFootprintFrontal: expected a number, found nothing'
    }

    def "what the engine refuses is named with the item's path"() {
        when:
        PlanFile.read(withoutItems(manualSurvey()) { it.polygon = it.polygon.take(2) })

        then:
        IllegalArgumentException e = thrown()
        e.message.startsWith('mission.items[1]: ')
    }

    def "another complex item without items is refused, saying which can be regenerated"() {
        when:
        PlanFile.read(withoutItems(manualSurvey()) { it.complexItemType = 'fwLandingPattern' })

        then:
        IllegalArgumentException e = thrown()
        e.message == "mission.items[1]: ComplexItem 'fwLandingPattern' has no TransectStyleComplexItem.Items to import," +
                ' and only surveys, corridor scans and structure scans can be regenerated; open and save the plan in' +
                ' QGroundControl to store its items'
    }

    def "a mapping item whose items are not the mission's at its seq is refused when written"() {
        given:
        MissionFile f = file(manualSurvey())
        MissionFile shifted = new MissionFile(f.mission(), f.fence(), f.rally(), f.vehicle(), [(1): f.mappingItems()[2]])

        when:
        PlanFile.write(shifted)

        then:
        IllegalArgumentException e = thrown()
        e.message == "item 1: the mission's items are not those of its survey 'survey', which starts there"
    }

    def "ABOVE_TERRAIN is written as QGroundControl's terrain frame mode"() {
        when:
        Map calc = json(PlanFile.write(file(manualSurvey(TransectOptions.defaults().withHeight(HeightReference.ABOVE_TERRAIN)))))
                .mission.items[1].TransectStyleComplexItem.CameraCalc

        then:
        calc.DistanceMode == 4
    }
}
