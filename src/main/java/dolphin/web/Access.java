package dolphin.web;

import com.sun.net.httpserver.Filter;
import com.sun.net.httpserver.HttpExchange;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.security.MessageDigest;
import java.util.Locale;
import java.util.Set;

/**
 * Who may read the web view (docs/guide.md, "The live web view"): it is read-only, so only GET and
 * HEAD pass. Bound to loopback it needs no token, but the Host header must name this machine (a web
 * page elsewhere cannot reach it by DNS rebinding); bound to another address every request needs the
 * token printed at start, from {@code ?token=} (then kept in a cookie for the page's own requests).
 */
final class Access extends Filter {

    static final String COOKIE = "dolphin-token";
    private static final Set<String> LOCAL_NAMES = Set.of("localhost", "127.0.0.1", "[::1]", "::1");

    private final String token;

    /** @param token the token every request must carry, or null for a loopback view */
    Access(String token) {
        this.token = token;
    }

    @Override
    public void doFilter(HttpExchange ex, Chain chain) throws IOException {
        String method = ex.getRequestMethod();
        if (!"GET".equals(method) && !"HEAD".equals(method)) {
            ex.getResponseHeaders().set("Allow", "GET, HEAD");
            Reply.text(ex, 405, "the web view is read-only: only GET and HEAD");
            return;
        }
        if (token == null) {
            if (!LOCAL_NAMES.contains(hostName(ex.getRequestHeaders().getFirst("Host")))) {
                Reply.text(ex, 403, "this web view serves loopback only: open it as http://127.0.0.1 or http://localhost");
                return;
            }
        } else {
            String given = queryToken(ex.getRequestURI().getRawQuery());
            boolean fromQuery = given != null;
            if (!fromQuery) {
                given = cookieToken(ex.getRequestHeaders().getFirst("Cookie"));
            }
            if (given == null || !MessageDigest.isEqual(given.getBytes(StandardCharsets.UTF_8), token.getBytes(StandardCharsets.UTF_8))) {
                Reply.text(ex, 401, "wrong or missing token: open the address that dolphin run printed, with its ?token=");
                return;
            }
            if (fromQuery) {
                ex.getResponseHeaders().add("Set-Cookie", COOKIE + "=" + token + "; Path=/; HttpOnly; SameSite=Strict");
            }
        }
        chain.doFilter(ex);
    }

    @Override
    public String description() {
        return "read-only access, by token beyond loopback";
    }

    /** The host of a Host header, without its port; "" when there is none. */
    static String hostName(String header) {
        if (header == null) {
            return "";
        }
        String h = header.strip().toLowerCase(Locale.ROOT);
        if (h.startsWith("[")) {
            int end = h.indexOf(']');
            return end < 0 ? h : h.substring(0, end + 1);
        }
        int colon = h.indexOf(':');
        return colon < 0 ? h : h.substring(0, colon);
    }

    static String queryToken(String rawQuery) {
        return parameter(rawQuery, "&", "token");
    }

    static String cookieToken(String cookies) {
        return parameter(cookies, ";", COOKIE);
    }

    private static String parameter(String text, String separator, String name) {
        if (text == null) {
            return null;
        }
        for (String part : text.split(separator)) {
            String p = part.strip();
            if (p.startsWith(name + "=")) {
                return p.substring(name.length() + 1);
            }
        }
        return null;
    }
}
