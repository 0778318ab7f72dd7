package dolphin.web;

/**
 * Where the web view listens: {@code PORT} (loopback) or {@code HOST:PORT}, an IPv6 host in
 * brackets ({@code [::1]:8080}). Port 0 takes a free port.
 */
public record WebAddress(String host, int port) {

    public static final String LOOPBACK = "127.0.0.1";

    public WebAddress {
        if (host == null || host.isBlank()) {
            throw new IllegalArgumentException("the host is empty");
        }
        if (port < 0 || port > 65535) {
            throw new IllegalArgumentException("the port must be between 0 and 65535, got " + port);
        }
    }

    public static WebAddress parse(String text) {
        String value = text.strip();
        int colon = value.lastIndexOf(':');
        String host = LOOPBACK;
        String port = value;
        if (colon >= 0 && !(value.startsWith("[") && value.endsWith("]"))) {
            host = value.substring(0, colon);
            port = value.substring(colon + 1);
            if (host.startsWith("[") && host.endsWith("]")) {
                host = host.substring(1, host.length() - 1);
            } else if (host.contains(":")) {
                throw new IllegalArgumentException("'" + text + "': write an IPv6 host in brackets, e.g. [::1]:8080");
            }
        }
        try {
            return new WebAddress(host, Integer.parseInt(port));
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("'" + text + "': expected [HOST:]PORT, e.g. 8080 or 0.0.0.0:8080");
        }
    }

    @Override
    public String toString() {
        return (host.contains(":") ? "[" + host + "]" : host) + ":" + port;
    }
}
