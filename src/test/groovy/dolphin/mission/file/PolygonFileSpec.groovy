package dolphin.mission.file

import dolphin.core.Position
import spock.lang.Specification
import spock.lang.TempDir

import java.nio.file.Files
import java.nio.file.Path

class PolygonFileSpec extends Specification {

    @TempDir
    Path dir

    static final List<List<Double>> FIELD = [[40.4442, -7.3752], [40.4460, -7.3752], [40.4460, -7.3720], [40.4442, -7.3720]]

    static List<List<Double>> degrees(List<Position> ps) {
        ps.collect { [Math.round(it.latitudeDegrees() * 1e7) / 1e7d, Math.round(it.longitudeDegrees() * 1e7) / 1e7d] }
    }

    Path file(String name, String text) {
        Path f = dir.resolve(name)
        Files.writeString(f, text)
        f
    }

    static String kmlRing(List<List<Double>> ll) {
        (ll + [ll[0]]).collect { "${it[1]},${it[0]},0" }.join(' ')
    }

    def "a KML Polygon's outer ring, its closing vertex dropped, heights 0"() {
        given:
        Path f = file('field.kml', """<?xml version="1.0" encoding="UTF-8"?>
<kml xmlns="http://www.opengis.net/kml/2.2"><Document><Placemark><name>field</name>
  <Polygon><outerBoundaryIs><LinearRing><coordinates>
    ${kmlRing(FIELD)}
  </coordinates></LinearRing></outerBoundaryIs>
  <innerBoundaryIs><LinearRing><coordinates>-7.374,40.445 -7.373,40.445 -7.373,40.4455 -7.374,40.445</coordinates></LinearRing></innerBoundaryIs>
  </Polygon></Placemark></Document></kml>
""")

        when:
        List<Position> polygon = PolygonFile.readPolygon(f)

        then:
        degrees(polygon) == FIELD
        polygon.every { it.hae() == 0 }
    }

    def "a KML LineString is a path; the first of several shapes is taken"() {
        given:
        String kml = """<kml xmlns="http://www.opengis.net/kml/2.2"><Document>
<Placemark><LineString><coordinates>-7.3752,40.4442 -7.3720,40.4460</coordinates></LineString></Placemark>
<Placemark><LineString><coordinates>1,2 3,4</coordinates></LineString></Placemark>
</Document></kml>"""

        expect:
        degrees(PolygonFile.polyline(kml)) == [[40.4442, -7.3752], [40.446, -7.372]]
    }

    def "a KML without the shape asked for says what it has"() {
        when:
        PolygonFile.readPolygon(file('road.kml', '<kml><Placemark><LineString><coordinates>1,2 3,4</coordinates></LineString></Placemark></kml>'))

        then:
        IllegalArgumentException e = thrown()
        e.message.endsWith('road.kml: no <Polygon> with an <outerBoundaryIs> ring in the KML; it has a <LineString>: read it as a path')
    }

    def "a bad KML tuple names its line"() {
        when:
        PolygonFile.polygon('<kml><Polygon><outerBoundaryIs><LinearRing><coordinates>\n1,2\n3,x\n</coordinates></LinearRing></outerBoundaryIs></Polygon></kml>')

        then:
        IllegalArgumentException e = thrown()
        e.message == "line 3, <coordinates> tuple 2: expected the latitude in degrees, found 'x'"
    }

    def "KML that is not well-formed names the line"() {
        when:
        PolygonFile.polygon('<kml>\n<Polygon>\n</kml>')

        then:
        IllegalArgumentException e = thrown()
        e.message.startsWith('line 3: not well-formed XML')
    }

    def "GeoJSON: a Polygon geometry, a Feature, a FeatureCollection's first Polygon"() {
        given:
        String ring = (FIELD + [FIELD[0]]).collect { "[${it[1]}, ${it[0]}]" }.join(', ')
        String polygon = """{"type": "Polygon", "coordinates": [[${ring}]]}"""

        expect:
        degrees(PolygonFile.polygon(polygon)) == FIELD
        degrees(PolygonFile.polygon("""{"type": "Feature", "properties": {}, "geometry": ${polygon}}""")) == FIELD
        degrees(PolygonFile.polygon("""{"type": "FeatureCollection", "features": [
            {"type": "Feature", "geometry": {"type": "Point", "coordinates": [1, 2]}},
            {"type": "Feature", "geometry": null},
            {"type": "Feature", "geometry": ${polygon}},
            {"type": "Feature", "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [1, 1]]]}}]}""")) == FIELD
        degrees(PolygonFile.polygon("""{"type": "MultiPolygon", "coordinates": [[[${ring}]]]}""")) == FIELD
    }

    def "GeoJSON: a LineString for a path"() {
        expect:
        degrees(PolygonFile.polyline('{"type": "Feature", "geometry": {"type": "LineString", "coordinates": [[-7.3752, 40.4442, 100], [-7.372, 40.446]]}}')) ==
                [[40.4442, -7.3752], [40.446, -7.372]]
    }

    def "GeoJSON errors give the JSON path and what was expected"() {
        when:
        PolygonFile.polygon(text)

        then:
        IllegalArgumentException e = thrown()
        e.message == message

        where:
        text                                                                                      | message
        '{"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [1, 95], [0, 0]]]}'                | 'coordinates[0][2][1] (latitude): 95 is out of range for a latitude (-90 to 90)'
        '{"type": "Feature", "geometry": {"type": "Polygon", "coordinates": [[[0, 0], [1]]]}}'     | 'geometry.coordinates[0][1]: expected [longitude, latitude] or [longitude, latitude, altitude], found 1 values'
        '{"type": "FeatureCollection", "features": [{"type": "Feature", "geometry": {"type": "Point", "coordinates": [1, 2]}}]}' | 'no Polygon or MultiPolygon in the GeoJSON; it has Point'
        '{"type": "Polygon", "coordinates": [[[0, 0], [1, 0], [0, 0]]]}'                         | 'coordinates[0]: a polygon needs at least 3 vertices, found 2 (the closing vertex not counted)'
        '{"a": 1}'                                                                                | 'the JSON is neither GeoJSON (it has no "type") nor a QGroundControl plan ("fileType": "Plan")'
    }

    static String plan(String items, String fence = '[]') {
        """{"fileType": "Plan", "version": 1, "mission": {"version": 2, "plannedHomePosition": [40.4, -7.3, 0], "items": ${items}},
            "geoFence": {"version": 2, "polygons": ${fence}, "circles": []}, "rallyPoints": {"version": 2, "points": []}}"""
    }

    def "a plan: a survey's polygon before the fence's, a corridor's polyline"() {
        given:
        String field = FIELD.collect { "[${it[0]}, ${it[1]}]" }.join(', ')
        String fence = """[{"version": 1, "inclusion": true, "polygon": [[1, 1], [1, 2], [2, 2]]}]"""

        expect:
        degrees(PolygonFile.polygon(plan("""[{"type": "SimpleItem"}, {"type": "ComplexItem", "complexItemType": "survey", "polygon": [${field}]}]""", fence))) == FIELD
        degrees(PolygonFile.polygon(plan('[]', fence))) == [[1, 1], [1, 2], [2, 2]]
        degrees(PolygonFile.polyline(plan("""[{"type": "ComplexItem", "complexItemType": "CorridorScan", "polyline": [[1, 1], [2, 2]]}]"""))) == [[1, 1], [2, 2]]
    }

    def "a plan without the shape says where it looked"() {
        when:
        PolygonFile.polyline(plan('[]'))

        then:
        IllegalArgumentException e = thrown()
        e.message == 'the plan has no polyline: no corridor scan in mission.items'
    }

    def "a .poly: lat lon lines, comments, the closing vertex dropped"() {
        given:
        Path f = file('field.poly', "#saved by Mission Planner 1.3.80\n" + (FIELD + [FIELD[0]]).collect { "${it[0]} ${it[1]}" }.join('\r\n') + '\n\n')

        expect:
        degrees(PolygonFile.readPolygon(f)) == FIELD
        degrees(PolygonFile.readPolyline(f)).size() == 5
    }

    def "a bad .poly line is named, with the file"() {
        given:
        Path f = file('field.poly', "# field\n40.1 -7.3\n40.2\n")

        when:
        PolygonFile.readPolygon(f)

        then:
        IllegalArgumentException e = thrown()
        e.message == "${f}: line 3: expected 'latitude longitude' in degrees (a .poly line; KML, GeoJSON and QGroundControl plans are also read), found '40.2'"
    }
}
