package dolphin.mission.file;

import dolphin.core.Position;
import groovy.json.JsonException;
import groovy.json.JsonSlurper;
import java.io.IOException;
import java.io.StringReader;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import javax.xml.parsers.ParserConfigurationException;
import javax.xml.parsers.SAXParserFactory;
import org.xml.sax.Attributes;
import org.xml.sax.InputSource;
import org.xml.sax.Locator;
import org.xml.sax.SAXException;
import org.xml.sax.SAXParseException;
import org.xml.sax.helpers.DefaultHandler;

/**
 * A polygon (a survey's area) or a polyline (a corridor's path) from the files map tools draw them
 * in, recognised by their content, not their name (docs/mission-files.md, "Polygon files"):
 * <ul>
 *   <li>KML (Google Earth, QGroundControl's KML import): the first {@code <Polygon>}'s
 *       {@code <outerBoundaryIs>} ring, or the first {@code <LineString>}; {@code <coordinates>}
 *       holds "lon,lat[,alt]" tuples;</li>
 *   <li>GeoJSON: the first Polygon (its outer ring) or MultiPolygon (its first polygon's), or the
 *       first LineString or MultiLineString, as a bare geometry, a Feature, or in a FeatureCollection
 *       or GeometryCollection; positions [lon, lat(, alt)];</li>
 *   <li>a QGroundControl plan: the first survey's or structure scan's {@code polygon}, else the first
 *       geofence polygon; a corridor scan's {@code polyline}; positions [lat, lon];</li>
 *   <li>Mission Planner's and MAVProxy's {@code .poly}: "lat lon" lines, {@code #} comments.</li>
 * </ul>
 * A file with several shapes gives its first, in document order (a plan: the mission's before the
 * fence's, since a plan that has a survey is most likely read for it). A ring's closing vertex (the
 * first repeated last, which KML, GeoJSON and .poly files have) is dropped. Heights are dropped:
 * every position is at height 0, as surveys take their heights from their own settings.
 */
public final class PolygonFile {

    private PolygonFile() {
    }

    /**
     * The polygon of a file, UTF-8 with or without a byte-order mark.
     *
     * @throws IllegalArgumentException starting with the file's name, saying where and what was expected
     */
    public static List<Position> readPolygon(Path file) throws IOException {
        return MissionFileText.parse(file, PolygonFile::polygon);
    }

    /**
     * The polyline of a file, UTF-8 with or without a byte-order mark.
     *
     * @throws IllegalArgumentException starting with the file's name, saying where and what was expected
     */
    public static List<Position> readPolyline(Path file) throws IOException {
        return MissionFileText.parse(file, PolygonFile::polyline);
    }

    /** The polygon of a file's text: at least 3 vertices, not closed. */
    public static List<Position> polygon(String text) {
        return read(text, true);
    }

    /** The polyline of a file's text: at least 2 vertices. */
    public static List<Position> polyline(String text) {
        return read(text, false);
    }

    private static List<Position> read(String text, boolean polygon) {
        String t = MissionFileText.withoutBom(text);
        String start = t.stripLeading();
        List<Position> points;
        String where;
        if (start.startsWith("<")) {
            int skipped = (int) t.substring(0, t.length() - start.length()).chars().filter(c -> c == '\n').count();
            VerticesFound s = kml(start, skipped, polygon);
            points = s.points;
            where = s.where;
        } else if (start.startsWith("{")) {
            VerticesFound s = json(start, polygon);
            points = s.points;
            where = s.where;
        } else {
            points = poly(t);
            where = ".poly file";
        }
        if (polygon && points.size() > 1 && points.get(0).equals(points.get(points.size() - 1))) {
            points.remove(points.size() - 1);
        }
        int least = polygon ? 3 : 2;
        if (points.size() < least) {
            throw new IllegalArgumentException(where + ": a " + (polygon ? "polygon" : "polyline") + " needs at least "
                    + least + " vertices, found " + points.size() + (polygon ? " (the closing vertex not counted)" : ""));
        }
        return List.copyOf(points);
    }

    /** The points read and where they were, for errors about the shape as a whole. */
    private record VerticesFound(List<Position> points, String where) {
    }

    private static Position position(double lat, double lon, String where) {
        if (!Double.isFinite(lat) || Math.abs(lat) > 90) {
            throw new IllegalArgumentException(where + ": latitude " + lat + " is out of range (-90 to 90)");
        }
        if (!Double.isFinite(lon) || Math.abs(lon) > 180) {
            throw new IllegalArgumentException(where + ": longitude " + lon + " is out of range (-180 to 180)");
        }
        return Position.fromDegrees(lat, lon, 0);
    }

    private static List<Position> poly(String text) {
        List<Position> points = new ArrayList<>();
        List<String> lines = text.lines().toList();
        for (int i = 0; i < lines.size(); i++) {
            String line = lines.get(i).strip();
            if (line.isEmpty() || line.startsWith("#")) {
                continue;
            }
            String where = "line " + (i + 1);
            String[] f = line.split("[\\s,]+");
            if (f.length != 2) {
                throw new IllegalArgumentException(where + ": expected 'latitude longitude' in degrees (a .poly line; KML,"
                        + " GeoJSON and QGroundControl plans are also read), found '" + shortened(line) + "'");
            }
            points.add(position(number(f[0], where, "latitude"), number(f[1], where, "longitude"), where));
        }
        return points;
    }

    private static double number(String s, String where, String what) {
        try {
            return Double.parseDouble(s);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException(where + ": expected the " + what + " in degrees, found '" + shortened(s) + "'", e);
        }
    }

    private static String shortened(String s) {
        return s.length() <= 60 ? s : s.substring(0, 60) + "...";
    }

    /** The first Polygon's outer ring or LineString's coordinates, with the line each tuple is on. */
    private static VerticesFound kml(String text, int skippedLines, boolean polygon) {
        KmlHandler handler = new KmlHandler(polygon);
        try {
            SAXParserFactory factory = SAXParserFactory.newInstance();
            factory.setNamespaceAware(true);
            // A KML has no DTD; refusing one keeps external entities out.
            factory.setFeature("http://apache.org/xml/features/disallow-doctype-decl", true);
            factory.newSAXParser().parse(new InputSource(new StringReader(text)), handler);
        } catch (SAXParseException e) {
            throw new IllegalArgumentException("line " + (e.getLineNumber() + skippedLines) + ": not well-formed XML ("
                    + e.getMessage() + "); expected a KML file", e);
        } catch (SAXException | ParserConfigurationException | IOException e) {
            throw new IllegalArgumentException("cannot read the XML: " + e.getMessage(), e);
        }
        if (handler.coordinates == null) {
            String wanted = polygon ? "<Polygon> with an <outerBoundaryIs> ring" : "<LineString>";
            throw new IllegalArgumentException("no " + wanted + " in the KML" + (handler.kml ? "" : " (the root element is not"
                    + " <kml>)") + (handler.other ? "; it has a " + (polygon ? "<LineString>: read it as a path"
                    : "<Polygon>: read it as a polygon") : ""));
        }
        return new VerticesFound(tuples(handler.coordinates.toString(), handler.line + skippedLines),
                "the KML's " + (polygon ? "<Polygon>" : "<LineString>") + " at line " + (handler.line + skippedLines));
    }

    /** "lon,lat[,alt]" tuples separated by white space; a tuple's errors name its line. */
    private static List<Position> tuples(String text, int firstLine) {
        List<Position> points = new ArrayList<>();
        // Some tools put spaces after the commas, which KML does not allow but readers accept.
        String t = text.replaceAll("[ \\t]*,[ \\t]*", ",");
        int line = firstLine;
        int i = 0;
        while (i < t.length()) {
            char c = t.charAt(i);
            if (Character.isWhitespace(c)) {
                line += c == '\n' ? 1 : 0;
                i++;
                continue;
            }
            int end = i;
            while (end < t.length() && !Character.isWhitespace(t.charAt(end))) {
                end++;
            }
            String tuple = t.substring(i, end);
            String where = "line " + line + ", <coordinates> tuple " + (points.size() + 1);
            String[] f = tuple.split(",", -1);
            if (f.length < 2 || f.length > 3) {
                throw new IllegalArgumentException(where + ": expected 'longitude,latitude[,altitude]', found '"
                        + shortened(tuple) + "'");
            }
            double lon = number(f[0], where, "longitude");
            double lat = number(f[1], where, "latitude");
            if (f.length == 3) {
                number(f[2], where, "altitude");
            }
            points.add(position(lat, lon, where));
            i = end;
        }
        return points;
    }

    /** Collects the text of the first matching {@code <coordinates>}, by the local names of its ancestors. */
    private static final class KmlHandler extends DefaultHandler {
        private final boolean polygon;
        private final List<String> path = new ArrayList<>();
        private Locator locator;
        private StringBuilder coordinates;
        private boolean collecting;
        private int line;
        private boolean kml;
        private boolean other;

        KmlHandler(boolean polygon) {
            this.polygon = polygon;
        }

        @Override
        public void setDocumentLocator(Locator l) {
            locator = l;
        }

        @Override
        public void startElement(String uri, String localName, String qName, Attributes attributes) {
            if (path.isEmpty()) {
                kml = localName.equals("kml");
            }
            path.add(localName);
            if (!localName.equals("coordinates")) {
                return;
            }
            boolean ring = endsWith("Polygon", "outerBoundaryIs", "LinearRing", "coordinates");
            boolean line = endsWith("LineString", "coordinates");
            if (coordinates == null && (polygon ? ring : line)) {
                coordinates = new StringBuilder();
                collecting = true;
                this.line = locator == null ? 1 : locator.getLineNumber();
            } else if (polygon ? line : ring) {
                other = true;
            }
        }

        private boolean endsWith(String... names) {
            int n = path.size();
            if (n < names.length) {
                return false;
            }
            for (int k = 0; k < names.length; k++) {
                if (!path.get(n - names.length + k).equals(names[k])) {
                    return false;
                }
            }
            return true;
        }

        @Override
        public void characters(char[] ch, int start, int length) {
            if (collecting) {
                coordinates.append(ch, start, length);
            }
        }

        @Override
        public void endElement(String uri, String localName, String qName) {
            path.remove(path.size() - 1);
            if (localName.equals("coordinates")) {
                collecting = false;
            }
        }
    }

    private static VerticesFound json(String text, boolean polygon) {
        Object root;
        try {
            root = new JsonSlurper().parseText(text);
        } catch (JsonException | IllegalArgumentException e) {
            throw new IllegalArgumentException("the text is not JSON (" + e.getMessage().lines().findFirst().orElse("")
                    + "); expected GeoJSON or a QGroundControl plan", e);
        }
        Map<?, ?> json = PlanJson.map(root, "the JSON");
        if ("Plan".equals(json.get("fileType"))) {
            return plan(json, polygon);
        }
        if (!(json.get("type") instanceof String)) {
            throw new IllegalArgumentException("the JSON is neither GeoJSON (it has no \"type\") nor a QGroundControl plan"
                    + " (\"fileType\": \"Plan\")");
        }
        List<String> seen = new ArrayList<>();
        VerticesFound found = geoJson(json, "", polygon, seen);
        if (found == null) {
            throw new IllegalArgumentException("no " + (polygon ? "Polygon or MultiPolygon" : "LineString or MultiLineString")
                    + " in the GeoJSON" + (seen.isEmpty() ? "" : "; it has " + String.join(", ", seen)));
        }
        return found;
    }

    /** The first matching geometry at or under {@code value}, or null; {@code seen} collects the other types. */
    private static VerticesFound geoJson(Map<?, ?> json, String where, boolean polygon, List<String> seen) {
        String at = where.isEmpty() ? "" : where + ".";
        Object type = json.get("type");
        if ("FeatureCollection".equals(type)) {
            List<?> features = PlanJson.list(json.get("features"), at + "features");
            for (int i = 0; i < features.size(); i++) {
                VerticesFound s = geoJson(PlanJson.map(features.get(i), at + "features[" + i + "]"), at + "features[" + i + "]",
                        polygon, seen);
                if (s != null) {
                    return s;
                }
            }
            return null;
        }
        if ("Feature".equals(type)) {
            Object geometry = json.get("geometry");
            return geometry == null ? null : geoJson(PlanJson.map(geometry, at + "geometry"), at + "geometry", polygon, seen);
        }
        if ("GeometryCollection".equals(type)) {
            List<?> geometries = PlanJson.list(json.get("geometries"), at + "geometries");
            for (int i = 0; i < geometries.size(); i++) {
                VerticesFound s = geoJson(PlanJson.map(geometries.get(i), at + "geometries[" + i + "]"),
                        at + "geometries[" + i + "]", polygon, seen);
                if (s != null) {
                    return s;
                }
            }
            return null;
        }
        String c = at + "coordinates";
        if (polygon && "Polygon".equals(type)) {
            return lonLats(first(json.get("coordinates"), c), c + "[0]");
        }
        if (polygon && "MultiPolygon".equals(type)) {
            return lonLats(first(first(json.get("coordinates"), c), c + "[0]"), c + "[0][0]");
        }
        if (!polygon && "LineString".equals(type)) {
            return lonLats(json.get("coordinates"), c);
        }
        if (!polygon && "MultiLineString".equals(type)) {
            return lonLats(first(json.get("coordinates"), c), c + "[0]");
        }
        if (!seen.contains(String.valueOf(type))) {
            seen.add(String.valueOf(type));
        }
        return null;
    }

    private static Object first(Object array, String where) {
        List<?> l = PlanJson.list(array, where);
        if (l.isEmpty()) {
            throw new IllegalArgumentException(where + ": expected at least one ring or line, found an empty array");
        }
        return l.get(0);
    }

    /** GeoJSON's [longitude, latitude(, altitude)] positions. */
    private static VerticesFound lonLats(Object array, String where) {
        return positions(array, where, true);
    }

    /** A plan's first survey or structure scan polygon, else its first fence polygon; or its first corridor's polyline. */
    private static VerticesFound plan(Map<?, ?> plan, boolean polygon) {
        String key = polygon ? "polygon" : "polyline";
        Object mission = plan.get("mission");
        if (mission != null) {
            Object items = PlanJson.map(mission, "mission").get("items");
            List<?> list = items == null ? List.of() : PlanJson.list(items, "mission.items");
            for (int i = 0; i < list.size(); i++) {
                Map<?, ?> item = PlanJson.map(list.get(i), "mission.items[" + i + "]");
                if ("ComplexItem".equals(item.get("type")) && item.get(key) != null) {
                    return latLons(item.get(key), "mission.items[" + i + "]." + key);
                }
            }
        }
        Object fence = plan.get("geoFence");
        if (polygon && fence != null) {
            Object polygons = PlanJson.map(fence, "geoFence").get("polygons");
            List<?> list = polygons == null ? List.of() : PlanJson.list(polygons, "geoFence.polygons");
            if (!list.isEmpty()) {
                return latLons(PlanJson.map(list.get(0), "geoFence.polygons[0]").get("polygon"), "geoFence.polygons[0].polygon");
            }
        }
        throw new IllegalArgumentException(polygon
                ? "the plan has no polygon: no survey or structure scan in mission.items, no polygon in geoFence.polygons"
                : "the plan has no polyline: no corridor scan in mission.items");
    }

    /** A plan's [latitude, longitude] positions. */
    private static VerticesFound latLons(Object array, String where) {
        return positions(array, where, false);
    }

    private static VerticesFound positions(Object array, String where, boolean longitudeFirst) {
        String order = longitudeFirst ? "[longitude, latitude]" : "[latitude, longitude]";
        int lat = longitudeFirst ? 1 : 0;
        int lon = 1 - lat;
        List<?> l = PlanJson.list(array, where);
        List<Position> points = new ArrayList<>();
        for (int i = 0; i < l.size(); i++) {
            String w = where + "[" + i + "]";
            List<?> p = PlanJson.list(l.get(i), w);
            if (p.size() < 2 || p.size() > 3) {
                throw new IllegalArgumentException(w + ": expected " + order + (longitudeFirst
                        ? " or [longitude, latitude, altitude]" : "") + ", found " + p.size() + " values");
            }
            points.add(Position.fromDegrees(PlanJson.degrees(p.get(lat), 90, w + "[" + lat + "] (latitude)"),
                    PlanJson.degrees(p.get(lon), 180, w + "[" + lon + "] (longitude)"), 0));
        }
        return new VerticesFound(points, where);
    }
}
