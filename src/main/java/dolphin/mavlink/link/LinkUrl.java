package dolphin.mavlink.link;

import java.net.InetSocketAddress;

/**
 * A parsed connection string: {@code udpin:HOST:PORT} (listen; learn each vehicle's address from its
 * datagrams), {@code udpout:HOST:PORT} (send to a fixed address), {@code tcp:HOST:PORT} (client) or
 * {@code serial:DEVICE:BAUD}.
 */
public record LinkUrl(Transport kind, String host, int port, String device, int baud, String text) {

    public enum Transport { UDPIN, UDPOUT, TCP, SERIAL }

    public static LinkUrl parse(String text) {
        String t = text == null ? "" : text.strip();
        int colon = t.indexOf(':');
        if (colon < 0) {
            throw bad(t, "expected KIND:ADDRESS, e.g. udpin:0.0.0.0:14559");
        }
        String scheme = t.substring(0, colon).toLowerCase(java.util.Locale.ROOT);
        String rest = t.substring(colon + 1);
        return switch (scheme) {
            case "udpin" -> hostPort(Transport.UDPIN, rest, t);
            case "udpout", "udp" -> hostPort(Transport.UDPOUT, rest, t);
            case "tcp" -> hostPort(Transport.TCP, rest, t);
            case "serial" -> serial(rest, t);
            default -> throw bad(t, "unknown link kind '" + scheme + "': expected udpin, udpout, tcp or serial");
        };
    }

    public InetSocketAddress address() {
        return new InetSocketAddress(host, port);
    }

    private static LinkUrl hostPort(Transport kind, String rest, String text) {
        int colon = rest.lastIndexOf(':');
        if (colon <= 0) {
            throw bad(text, "expected HOST:PORT after '" + kind.name().toLowerCase(java.util.Locale.ROOT) + ":'");
        }
        String host = rest.substring(0, colon);
        int port = number(rest.substring(colon + 1), text, "port");
        int lowest = kind == Transport.UDPIN ? 0 : 1;
        if (port < lowest || port > 65535) {
            throw bad(text, "the port must be between " + lowest + " and 65535, got " + port
                    + (kind == Transport.UDPIN ? " (0 listens on any free port)" : ""));
        }
        return new LinkUrl(kind, host, port, null, 0, text);
    }

    private static LinkUrl serial(String rest, String text) {
        int colon = rest.lastIndexOf(':');
        if (colon <= 0) {
            throw bad(text, "expected DEVICE:BAUD after 'serial:', e.g. serial:/dev/ttyUSB0:57600");
        }
        int baud = number(rest.substring(colon + 1), text, "baud rate");
        if (baud <= 0) {
            throw bad(text, "the baud rate must be positive, got " + baud);
        }
        return new LinkUrl(Transport.SERIAL, null, 0, rest.substring(0, colon), baud, text);
    }

    private static int number(String s, String text, String what) {
        try {
            return Integer.parseInt(s);
        } catch (NumberFormatException e) {
            throw bad(text, "the " + what + " must be a number, got '" + s + "'");
        }
    }

    private static IllegalArgumentException bad(String text, String why) {
        return new IllegalArgumentException("bad connection string '" + text + "': " + why);
    }

    @Override
    public String toString() {
        return text;
    }
}
