package dolphin.mission.survey;

import dolphin.dsl.vocabulary.Suggestions;
import java.util.Comparator;
import java.util.List;
import java.util.Locale;
import java.util.Optional;

/** QGroundControl's named cameras, all landscape, as in docs/qgc-surveys.md §1.5 (names as QGC spells them). */
public final class Cameras {

    private static final List<Camera> ALL = List.of(
            cam("Canon S100 PowerShot", 7.6, 5.7, 4000, 3000, 5.2, 0, false),
            cam("Canon EOS-M 22mm", 22.3, 14.9, 5184, 3456, 22, 0, false),
            cam("Canon G9 X PowerShot", 13.2, 8.8, 5488, 3680, 10.2, 0, false),
            cam("Canon SX260 HS PowerShot", 6.17, 4.55, 4000, 3000, 4.5, 0, false),
            cam("GoPro Hero 4", 6.17, 4.55, 4000, 3000, 2.98, 0, false),
            cam("Parrot Sequioa RGB", 6.17, 4.63, 4608, 3456, 4.9, 1, false),
            cam("Parrot Sequioa Monochrome", 4.8, 3.6, 1280, 960, 4.0, 0.8, false),
            cam("RedEdge", 4.8, 3.6, 1280, 960, 5.5, 0, false),
            cam("Ricoh GR II", 23.7, 15.7, 4928, 3264, 18.3, 0, false),
            cam("Sentera Double 4K Sensor", 6.2, 4.65, 4000, 3000, 5.4, 0.8, false),
            cam("Sentera NDVI Single Sensor", 4.68, 3.56, 1248, 952, 4.14, 0.5, false),
            cam("Sentera 6X Sensor", 6.57, 4.93, 1904, 1428, 8.0, 0.2, false),
            cam("Sentera 65R Sensor", 29.9, 22.4, 9344, 7000, 27.4, 0.3, false),
            cam("Sony a6000 16mm", 23.5, 15.6, 6000, 4000, 16, 1.0, false),
            cam("Sony a6000 35mm", 23.5, 15.6, 6000, 4000, 35, 1.0, false),
            cam("Sony a6300 Zeiss 21mm f/2.8", 23.5, 15.6, 6000, 4000, 21, 1.0, false),
            cam("Sony a6300 Sony 28mm f/2.0", 23.5, 15.6, 6000, 4000, 28, 1.0, false),
            cam("Sony a7R II Zeiss 21mm f/2.8", 35.814, 23.876, 7952, 5304, 21, 1.0, true),
            cam("Sony a7R II Sony 28mm f/2.0", 35.814, 23.876, 7952, 5304, 28, 1.0, true),
            cam("Sony a7r III 35mm", 35.9, 24.0, 7952, 5304, 35, 1.0, false),
            cam("Sony a7r IV 35mm", 35.7, 23.8, 9504, 6336, 35, 1.0, false),
            cam("Sony DSC-QX30U @ 4.3mm f/3.5", 7.82, 5.865, 5184, 3888, 4.3, 2.0, false),
            cam("Sony DSC-RX0", 13.2, 8.8, 4800, 3200, 7.7, 0, false),
            cam("Sony DSC-RX1R II 35mm", 35.9, 24.0, 7952, 5304, 35, 1.0, false),
            cam("Sony ILCE-QX1", 23.2, 15.4, 5456, 3632, 16, 0, false),
            cam("Sony NEX-5R 20mm", 23.2, 15.4, 4912, 3264, 20, 1, false),
            cam("Sony RX100 II 28mm", 13.2, 8.8, 5472, 3648, 10.4, 0, false),
            cam("Yuneec CGOET", 5.6405, 3.1813, 1920, 1080, 3.5, 1.3, true),
            cam("Yuneec E10T", 5.6405, 3.1813, 1920, 1080, 23, 1.3, true),
            cam("Yuneec E50", 6.2372, 4.7058, 4000, 3000, 7.2, 1.3, true),
            cam("Yuneec E90", 13.3056, 8.656, 5472, 3648, 8.29, 1.3, true),
            cam("Flir Duo R", 160, 120, 1920, 1080, 1.9, 0, false),
            cam("Flir Duo Pro R", 10.88, 8.704, 640, 512, 19, 1.0, false),
            cam("Workswell Wiris Security Thermal Camera", 13.6, 10.2, 800, 600, 35, 1.8, false),
            cam("Workswell Wiris Security Visual Camera", 4.826, 3.556, 1920, 1080, 4.3, 1.8, false));

    private Cameras() {
    }

    private static Camera cam(String name, double sw, double sh, int iw, int ih, double f, double minInterval,
                              boolean fixed) {
        return new Camera(name, sw, sh, iw, ih, f, minInterval, fixed);
    }

    public static List<Camera> all() {
        return ALL;
    }

    /** The camera of that canonical name, case aside. */
    public static Optional<Camera> named(String name) {
        return ALL.stream().filter(c -> c.name().equalsIgnoreCase(name.trim())).findFirst();
    }

    /**
     * Up to {@code max} camera names a mistyped one may stand for, nearest first: names that
     * contain it (or it contains), then names within a few edits (about one in four letters).
     */
    public static List<String> closest(String name, int max) {
        String n = normal(name);
        if (n.isEmpty() || max <= 0) {
            return List.of();
        }
        int allowed = Math.max(2, n.length() / 4);
        return ALL.stream().map(Camera::name)
                .map(c -> new Scored(c, score(normal(c), n)))
                .filter(s -> s.score <= allowed)
                .sorted(Comparator.comparingInt(Scored::score).thenComparing(Scored::name))
                .limit(max)
                .map(Scored::name)
                .toList();
    }

    private record Scored(String name, int score) {
    }

    /** 0 when one name holds the other, else the edit distance. */
    private static int score(String candidate, String typed) {
        if (candidate.contains(typed) || typed.contains(candidate)) {
            return 0;
        }
        return Suggestions.distance(candidate, typed);
    }

    private static String normal(String s) {
        return s.toLowerCase(Locale.ROOT).replaceAll("[\\s_-]+", " ").trim();
    }
}
