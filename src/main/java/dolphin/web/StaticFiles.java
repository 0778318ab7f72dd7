package dolphin.web;

import com.sun.net.httpserver.HttpExchange;
import com.sun.net.httpserver.HttpHandler;
import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.util.Map;
import java.util.Properties;

/**
 * The page (index.html, app.js, app.css from this package's resources) and Leaflet under
 * {@code /leaflet/}, from its WebJar on the class path: nothing is fetched from elsewhere.
 */
final class StaticFiles implements HttpHandler {

    private static final String PAGE = "/dolphin/web/";
    private static final String WEBJAR = "/META-INF/resources/webjars/leaflet/";
    private static final Map<String, String> TYPES = Map.of("html", "text/html; charset=utf-8",
            "js", "text/javascript; charset=utf-8", "css", "text/css; charset=utf-8", "png", "image/png",
            "svg", "image/svg+xml");
    private static final Map<String, String> PAGES = Map.of("/", "index.html", "/index.html", "index.html",
            "/app.js", "app.js", "/app.css", "app.css");

    private final String leafletDist = WEBJAR + leafletVersion() + "/dist/";

    @Override
    public void handle(HttpExchange ex) throws IOException {
        String path = ex.getRequestURI().getPath();
        String resource = PAGES.containsKey(path) ? PAGE + PAGES.get(path)
                : path.startsWith("/leaflet/") && !path.contains("..") ? leafletDist + path.substring("/leaflet/".length())
                : null;
        try (InputStream in = resource == null ? null : StaticFiles.class.getResourceAsStream(resource)) {
            if (in == null) {
                Reply.text(ex, 404, "no such page: " + path);
                return;
            }
            String extension = resource.substring(resource.lastIndexOf('.') + 1);
            Reply.send(ex, 200, TYPES.getOrDefault(extension, "application/octet-stream"), in.readAllBytes());
        }
    }

    /** The Leaflet version of the WebJar on the class path, from its Maven properties. */
    static String leafletVersion() {
        try (InputStream in = StaticFiles.class.getResourceAsStream("/META-INF/maven/org.webjars.npm/leaflet/pom.properties")) {
            if (in == null) {
                throw new IllegalStateException("the Leaflet WebJar (org.webjars.npm:leaflet) is not on the class path");
            }
            Properties p = new Properties();
            p.load(in);
            return p.getProperty("version");
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}
