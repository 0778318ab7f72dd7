package dolphin.mission.survey

import com.MAVLink.enums.MAV_CMD
import dolphin.core.Position
import dolphin.mission.model.MissionItem
import groovy.json.JsonSlurper
import spock.lang.Requires
import spock.lang.Shared
import spock.lang.Specification

import java.nio.file.Files
import java.nio.file.Path

/**
 * The QGroundControl plans of the corpus's surveys/ folder (named by -Ddolphin.missionFiles, as for
 * RealMissionFilesSpec): every complex item rebuilt from its outline and its STORED CameraCalc
 * values (QGC does not recompute them on load, docs/qgc-surveys.md §1.3) must give the items QGC
 * stored, in the emission generation the table below names for it (§5), or for terrain-following
 * surveys the coordinates QGC drew. Skipped without the corpus; with it named, fails when a file
 * is missing or not in the table.
 */
@Requires({ System.getProperty('dolphin.missionFiles') })
class SurveyCorpusSpec extends Specification {

    static final Path SURVEYS = Path.of(System.getProperty('dolphin.missionFiles', '.')).resolve('surveys')

    /** Metres: how far our positions may lie from QGC's. */
    static final double TOLERANCE = 0.5

    static final String TERRAIN = 'terrain'
    static final String STRUCTURE = 'structure'
    static final String EDITED = 'skip: edited by a third-party tool after QGroundControl (arc turns'

    /**
     * Per file, per complex item in order: the Emission that wrote its items (docs §5, §2.8), or
     * TERRAIN (CalcAboveTerrain: items hold terrain samples, compare the drawn path only), STRUCTURE
     * (no items stored), or why it is skipped.
     */
    static final Map<String, List<String>> TABLE = [
            'DroneIcarus+Icarus-DroneOptimiser/MissionPlans/survey4.plan'                          : ['LEGACY_SURVEY'],
            'DroneIcarus+Icarus-DroneOptimiser/surveyAudit.plan'                                   : ['LEGACY_SURVEY'],
            'ZilantRobotics+innopolis_vtol_dynamics/tests/inspection/technopark_survey_full_town.plan': ['CURRENT'],
            'ZilantRobotics+innopolis_vtol_dynamics/tests/inspection/technopark_structure_scan.plan' : [STRUCTURE],
            'eKerney+dataStore2/KZOO-TEST.plan'                                                    : [TERRAIN],
            'eKerney+dataStore2/KZOO-CORR.plan'                                                    : ['CURRENT_NO_LABEL_SWAP'],
            'mavlink+MAVSDK/src/plugins/mission/qgroundcontrol_sample_with_survey.plan'            : ['LEGACY_SURVEY', 'LEGACY_CORRIDOR'],
            'gisma+uavRmp/inst/extdata/qgc_survey.plan'                                            : ['LEGACY_SURVEY'],
            'gisma+uavRmp/inst/extdata/tutdata_qgc_survey.plan'                                    : ['LEGACY_SURVEY'],
            'gisma+uavRmp/inst/extdata/tutdata_qgc_survey30m.plan'                                 : [TERRAIN],
            'ken-hsu+pathplanning/wp1.plan'                                                        : [TERRAIN],
            'ken-hsu+pathplanning/waypoint1.plan'                                                  : [EDITED + ' and terrain waypoints, no camera triggers)'],
            'ken-hsu+pathplanning/FT01_original.plan'                                              : [EDITED + ' replace the straight transects)'],
            'szyfrowac+Autonomous-Drone/mission.plan'                                              : ['CURRENT'],
    ]

    /** Every compared item's worst position difference, metres. */
    @Shared
    Map<String, Double> worst = [:]

    /** The same before our items round positions to degE7: path() against QGC's coordinates, metres. */
    @Shared
    Map<String, Double> worstPath = [:]

    def cleanupSpec() {
        if (!worst.isEmpty()) {
            Map.Entry<String, Double> w = worst.max { it.value }
            System.out.printf('survey corpus: %d complex items compared, worst position difference %.3g m (%s);'
                    + ' before degE7 rounding %.3g m%n', worst.size(), w.value, w.key, worstPath.values().max())
        }
    }

    static List<String> planFiles() {
        if (!Files.isDirectory(SURVEYS)) {
            throw new IllegalStateException("the survey plans are missing: expected $SURVEYS")
        }
        Files.walk(SURVEYS).withCloseable { s ->
            s.filter { it.toString().endsWith('.plan') }.collect { SURVEYS.relativize(it).toString().replace('\\', '/') }.sort()
        }
    }

    /** [file, index in the file's complex items, what the table says, the item's JSON]. */
    static List<List> rows(Closure<Boolean> which) {
        planFiles().collectMany { String file ->
            List<Map> complex = (read(file).mission.items as List<Map>).findAll { it.type == 'ComplexItem' }
            List<String> said = TABLE[file] ?: []
            (0..<complex.size()).collect { int i -> [file, i, i < said.size() ? said[i] : null, complex[i]] }
        }.findAll { which(it[2] as String) }
    }

    static Map read(String file) {
        new JsonSlurper().parse(SURVEYS.resolve(file).toFile()) as Map
    }

    def "the table names every survey plan and each of its complex items"() {
        expect:
        planFiles() == TABLE.keySet().sort()
        planFiles().every { (read(it).mission.items as List<Map>).count { it.type == 'ComplexItem' } == TABLE[it].size() }
    }

    def "#file item #index gives the items QGroundControl stored (#generation)"() {
        given:
        Map ts = json.TransectStyleComplexItem as Map
        List<Map> stored = ts.Items as List<Map>
        MappingItem ours = build(json, Emission.valueOf(generation))
        int first = stored[0].doJumpId as int
        List<MissionItem> items = ours.items(first)
        List<Double> offsets = []
        // before degE7 rounding: our path against the stored waypoints (one waypoint per path point here)
        List<List> waypoints = stored.findAll { it.command == MAV_CMD.MAV_CMD_NAV_WAYPOINT }*.params
        List<Double> unrounded = [ours.path(), waypoints].transpose().collect { TransectPoint t, List p ->
            haversine(t.latitude(), t.longitude(), p[4] as double, p[5] as double)
        }

        expect:
        items.size() == stored.size()
        items*.command == stored*.command
        items*.seq == stored*.doJumpId
        [items, stored].transpose().every { MissionItem o, Map e ->
            List p = e.params as List
            if (o.command() == MAV_CMD.MAV_CMD_NAV_WAYPOINT) {
                offsets << metres(o, p[4] as double, p[5] as double)
                assert MissionItem.altitudeReference(o.frame()) == e.frame
                assert o.z() == (p[6] as float)
                assert o.param1() == (p[0] as float)
            } else {
                assert o.frame() == e.frame
                assert o.param1() == (p[0] as float)
                assert o.param3() == (p[2] as float)
            }
            true
        }
        offsets.max() < TOLERANCE
        ours.path().size() == waypoints.size()
        ts.CameraShots == null || ours.coverage().photos() == ts.CameraShots

        cleanup:
        if (!offsets.isEmpty()) {
            worst["$file #$index"] = offsets.max()
            worstPath["$file #$index"] = unrounded.max()
            System.out.printf('%s #%d %s %s: %d items, worst %.2e m (path before degE7 rounding %.2e m); photos %d'
                    + ' (QGC CameraShots %s)%n', file, index, ours?.qgcType(), generation, items?.size(), offsets.max(),
                    unrounded.max(), ours?.coverage()?.photos(), ts.CameraShots ?: '-')
        }

        where:
        [file, index, generation, json] << rows { it != null && it in Emission.values()*.name() }
    }

    def "#file item #index: the terrain-following survey's drawn path"() {
        given:
        List<List> drawn = json.TransectStyleComplexItem.VisualTransectPoints as List<List>
        MappingItem ours = build(json, Emission.CURRENT)
        List<TransectPoint> path = ours.path()
        List<Double> offsets = [path, drawn].transpose().collect { TransectPoint t, List d ->
            haversine(t.latitude(), t.longitude(), d[0] as double, d[1] as double)
        }

        expect:
        ours.photoGrid().altitude() == json.TransectStyleComplexItem.CameraCalc.DistanceToSurface
        path.size() == drawn.size()
        offsets.max() < TOLERANCE

        cleanup:
        if (!offsets.isEmpty()) {
            worst["$file #$index"] = offsets.max()
            worstPath["$file #$index"] = offsets.max()
            System.out.printf('%s #%d %s terrain: %d path points, worst %.2e m%n', file, index, ours?.qgcType(),
                    path?.size(), offsets.max())
        }

        where:
        [file, index, generation, json] << rows { it == TERRAIN }
    }

    def "#file item #index: the structure scan's count and layers"() {
        given:
        Map cc = json.CameraCalc as Map
        List<List> polygon = json.polygon as List<List>
        StructureScan scan = new StructureScan('structureScan', positions(polygon),
                PhotoGrid.manual(cc.DistanceToSurface as double, cc.AdjustedFootprintSide as double,
                        cc.AdjustedFootprintFrontal as double),
                json.StructureHeight as double, json.ScanBottomAlt as double, json.EntranceAltitude as double,
                json.StartFromTop as boolean, json.GimbalPitch as double)
        int n = polygon.size()
        int layers = json.Layers as int
        double h = cc.AdjustedFootprintFrontal as double
        List<MissionItem> items = scan.items(1)
        List<Float> ringAltitudes = items.findAll { it.command() == MAV_CMD.MAV_CMD_NAV_WAYPOINT }.drop(1).dropRight(1)*.z()
        List<Double> expected = (0..<layers).collect { k ->
            json.StartFromTop ? (json.StructureHeight as double) - h / 2 - k * h : (json.ScanBottomAlt as double) + h / 2 + k * h
        }

        expect:
        scan.layers() == layers
        items.size() == (n + 3) * layers + 4
        ringAltitudes == expected.collectMany { [it as float] * (n + 1) }
        items.first().z() == (json.EntranceAltitude as float) && items.last().z() == (json.EntranceAltitude as float)

        cleanup:
        System.out.printf('%s #%d StructureScan: %d vertices, %d layers, %d items%n', file, index, n, scan?.layers(),
                items?.size())

        where:
        [file, index, generation, json] << rows { it == STRUCTURE }
    }

    def "#file item #index is skipped: #generation"() {
        expect:
        generation.startsWith('skip: ')
        json.TransectStyleComplexItem.Items

        where:
        [file, index, generation, json] << rows { it?.startsWith('skip: ') }
    }

    /** Our item from the plan's outline and stored CameraCalc values. */
    static MappingItem build(Map json, Emission emission) {
        Map ts = json.TransectStyleComplexItem as Map
        Map cc = ts.CameraCalc as Map
        TransectOptions options = new TransectOptions(ts.TurnAroundDistance as double, ts.CameraTriggerInTurnAround as boolean,
                ts.HoverAndCapture as boolean, ts.Refly90Degrees as boolean, height(ts, cc), emission)
        if (json.complexItemType == 'survey') {
            return new PolygonSurvey('survey', positions(json.polygon as List), grid(cc), json.angle as double,
                    EntryCorner.ofQgc(json.entryLocation as int), (json.flyAlternateTransects ?: false) as boolean, options)
        }
        new CorridorScan('corridorScan', positions(json.polyline as List), json.CorridorWidth as double, grid(cc),
                EntryCorner.ofQgc(json.EntryPoint as int), options)
    }

    /** The stored grid: QGC keeps AdjustedFootprintSide/Frontal from the file (§1.3). */
    static PhotoGrid grid(Map cc) {
        if (cc.CameraName == 'Manual (no camera specs)') {
            return PhotoGrid.manual(cc.DistanceToSurface as double, cc.AdjustedFootprintSide as double,
                    cc.AdjustedFootprintFrontal as double)
        }
        Camera camera = new Camera(cc.CameraName as String, cc.SensorWidth as double, cc.SensorHeight as double,
                cc.ImageWidth as int, cc.ImageHeight as int, cc.FocalLength as double, cc.MinTriggerInterval as double,
                cc.FixedOrientation as boolean)
        double gsd = cc.ImageDensity as double
        boolean landscape = cc.Landscape as boolean
        new PhotoGrid(camera, landscape, cc.ValueSetIsDistance as boolean, cc.DistanceToSurface as double, gsd,
                cc.FrontalOverlap as double, cc.SideOverlap as double,
                (landscape ? camera.imageWidth() : camera.imageHeight()) * gsd / 100,
                (landscape ? camera.imageHeight() : camera.imageWidth()) * gsd / 100,
                cc.AdjustedFootprintSide as double, cc.AdjustedFootprintFrontal as double)
    }

    /** §2.9: FollowTerrain (TransectStyle v1), DistanceMode (CameraCalc v2) or DistanceToSurfaceRelative (v1). */
    static HeightReference height(Map ts, Map cc) {
        if (ts.FollowTerrain) {
            return HeightReference.ABOVE_TERRAIN
        }
        if (cc.containsKey('DistanceMode')) {
            return HeightReference.ofQgcDistanceMode(cc.DistanceMode as int)
        }
        cc.DistanceToSurfaceRelative ? HeightReference.ABOVE_HOME : HeightReference.ABOVE_SEA_LEVEL
    }

    static List<Position> positions(List<List> latLon) {
        latLon.collect { Position.fromDegrees(it[0] as double, it[1] as double, 0) }
    }

    static double metres(MissionItem o, double lat, double lon) {
        haversine(o.x() * 1e-7, o.y() * 1e-7, lat, lon)
    }

    /** Great-circle distance on the mean Earth sphere, metres. */
    static double haversine(double lat1, double lon1, double lat2, double lon2) {
        double p1 = Math.toRadians(lat1), p2 = Math.toRadians(lat2)
        double a = Math.sin((p2 - p1) / 2)**2 + Math.cos(p1) * Math.cos(p2) * Math.sin(Math.toRadians(lon2 - lon1) / 2)**2
        return 6_371_008.8 * 2 * Math.asin(Math.sqrt(a))
    }
}
