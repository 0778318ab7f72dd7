package dolphin.web;

import com.MAVLink.common.msg_statustext;
import com.sun.net.httpserver.HttpContext;
import com.sun.net.httpserver.HttpServer;
import dolphin.core.Clock;
import dolphin.core.TaskEvent;
import dolphin.core.TaskTree;
import dolphin.core.VehicleEvent;
import dolphin.dsl.Engine;
import dolphin.dsl.EngineListener;
import dolphin.dsl.ScriptResult;
import dolphin.mavlink.MAVLinkCommunications;
import dolphin.mavlink.StatusText;
import java.io.IOException;
import java.net.BindException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.UnknownHostException;
import java.nio.charset.StandardCharsets;
import java.security.SecureRandom;
import java.time.Duration;
import java.util.HexFormat;
import java.util.LinkedHashMap;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.atomic.AtomicInteger;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The live web view of a run (docs/guide.md, "The live web view"): a page with the map of the
 * vehicles, the task trees and the event log, and the JSON stream behind it (docs/embedding.md).
 * It listens to the engine, samples the fleet every {@link #PERIOD} of the display clock and serves
 * over the JDK's HTTP server. Read-only: nothing from the page reaches the run or a vehicle.
 */
public final class WebView implements EngineListener, AutoCloseable {

    private static final Logger LOG = LoggerFactory.getLogger(WebView.class);

    /** How often the fleet is sampled and viewers are sent a frame: 4 Hz. */
    public static final Duration PERIOD = Duration.ofMillis(250);
    static final int LOG_CAPACITY = 2000;

    /**
     * @param address where to listen
     * @param tiles a tile URL template ({@code https://tile.openstreetmap.org/{z}/{x}/{y}.png}), or
     *        null for a plain background
     */
    public record Settings(WebAddress address, String tiles) {
    }

    private final Engine engine;
    private final Clock runClock;
    private final Clock displayClock;
    private final double origin;
    private final TaskBoard board;
    private final EventLog log = new EventLog(LOG_CAPACITY);
    private final FleetFeed feed;
    private final Broadcast broadcast;
    private final String configJson;
    private final HttpServer server;
    private final ExecutorService viewers;
    private final String token;
    private final Thread sampler;
    private final EventStream stream;
    private volatile String script = "";
    private volatile String outcome;
    private volatile boolean running = true;

    private WebView(Settings config, MAVLinkCommunications comms, Engine engine, Clock displayClock) throws WebViewException {
        this.engine = engine;
        this.runClock = engine.getEnvironment().getClock();
        this.displayClock = displayClock;
        this.origin = runClock.seconds();
        this.board = new TaskBoard(origin);
        this.feed = new FleetFeed(new MavlinkFleet(comms::nodes, () -> engine.getEnvironment().getBound(), board),
                () -> comms.linkHealth().stream().map(LinkView::of).toList(), board);
        this.broadcast = new Broadcast(displayClock, feed.latest());
        Map<String, Object> settings = new LinkedHashMap<>();
        settings.put("tiles", config.tiles());
        settings.put("periodMillis", PERIOD.toMillis());
        this.configJson = Json.write(settings);
        InetAddress host = resolve(config.address());
        this.token = host.isLoopbackAddress() ? null : newToken();
        this.server = bind(config.address(), host);
        this.stream = new EventStream(broadcast, log, this::snapshot, this::run);
        AtomicInteger threads = new AtomicInteger();
        this.viewers = Executors.newCachedThreadPool(r -> {
            Thread t = new Thread(r, "dolphin web " + threads.incrementAndGet());
            t.setDaemon(true);
            return t;
        });
        Access access = new Access(token);
        StaticFiles files = new StaticFiles();
        for (HttpContext c : new HttpContext[] {server.createContext("/", files), server.createContext("/events", stream),
                server.createContext("/state",
                ex -> Reply.send(ex, 200, "application/json; charset=utf-8", snapshot(feed.latest()).getBytes(StandardCharsets.UTF_8)))}) {
            c.getFilters().add(access);
        }
        server.setExecutor(viewers);
        // MessageHandler keeps its consumers: a closed view ignores what still comes.
        comms.messageHandler().on(msg_statustext.class, (n, m) -> {
            if (running) {
                log.add(now(), "vehicle", n.getId(), StatusText.of(m));
            }
        });
        this.sampler = new Thread(this::sampleLoop, "dolphin web sampler");
        sampler.setDaemon(true);
    }

    /**
     * Starts serving the view of a run: the engine's events from now on, the communications' vehicles.
     *
     * @throws WebViewException naming the address and what is wrong with it (in use, unknown host...)
     */
    public static WebView start(Settings config, MAVLinkCommunications comms, Engine engine, Clock displayClock)
            throws WebViewException {
        WebView view = new WebView(config, comms, engine, displayClock);
        engine.addListener(view);
        view.server.start();
        view.sampler.start();
        return view;
    }

    /** The page's address, with the token when one is needed. */
    public String address() {
        InetSocketAddress a = server.getAddress();
        String host = a.getAddress().getHostAddress();
        return "http://" + (host.contains(":") ? "[" + host + "]" : host) + ":" + a.getPort() + "/"
                + (token == null ? "" : "?token=" + token);
    }

    /** The viewers streaming now. */
    public int viewers() {
        return stream.viewers();
    }

    private double now() {
        return runClock.seconds() - origin;
    }

    private void sampleLoop() {
        try {
            while (running) {
                try {
                    broadcast.publish(feed.sample(now()));
                } catch (RuntimeException e) {
                    LOG.warn("web view: a sample failed", e);
                }
                displayClock.sleep(PERIOD);
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /** The first message of a stream and the answer of /state: everything, tracks and settings included. */
    private String snapshot(FleetFeed.FeedFrame frame) {
        return FleetFeed.update(frame, 0, log.since(0), run() + ",\"tracks\":" + feed.tracksJson() + ",\"config\":" + configJson);
    }

    /** The script and how it ended (null while it runs), in every message. */
    private String run() {
        Map<String, Object> run = new LinkedHashMap<>();
        run.put("script", script);
        run.put("outcome", outcome);
        return ",\"run\":" + Json.write(run);
    }

    @Override
    public void message(String text) {
        log.add(now(), "message", null, text);
    }

    @Override
    public void executeStarted(TaskTree tree) {
        board.executeStarted(tree);
    }

    @Override
    public void taskEvent(TaskEvent event) {
        board.taskEvent(event);
        if (event.isPlatformTask()) {
            String what = switch (event.kind()) {
                case STARTED -> "started";
                case STOPPED -> "stopped";
                case COMPLETED -> event.state().isError() ? "ended in ERROR: " + event.state().getMessage() : "done";
            };
            log.add(event.time() - origin, event.state().isError() ? "error" : "task",
                    event.vehicles().isEmpty() ? null : String.join(",", event.vehicles()), "task " + event.task().getId() + " " + what);
        }
    }

    /** On the thread that raised it; the log is synchronized. Its kind in lower case is the entry's: contact_lost, ... */
    @Override
    public void vehicleEvent(VehicleEvent event) {
        log.add(event.time() - origin, event.kind().name().toLowerCase(Locale.ROOT), event.vehicle(), event.text());
    }

    @Override
    public void scriptStarted(String name) {
        script = name;
        log.add(now(), "script", null, name + " started");
    }

    @Override
    public void scriptFinished(String name, ScriptResult result) {
        outcome = result.outcome().name().toLowerCase(Locale.ROOT);
        log.add(now(), result.exitCode() == 0 ? "script" : "error", null, result.error() != null ? result.error().toString()
                : name + ": " + outcome + (result.message() == null ? "" : " (" + result.message() + ")"));
    }

    /** Sends the last frame and an end to every viewer, then stops serving (at most a second later). */
    @Override
    public void close() {
        engine.removeListener(this);
        running = false;
        sampler.interrupt();
        try {
            sampler.join(2000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        broadcast.publish(feed.sample(now()));
        broadcast.end();
        server.stop(1);
        viewers.shutdownNow();
    }

    private static InetAddress resolve(WebAddress address) throws WebViewException {
        try {
            return InetAddress.getByName(address.host());
        } catch (UnknownHostException e) {
            throw new WebViewException("--web " + address + ": unknown host " + address.host());
        }
    }

    private static HttpServer bind(WebAddress address, InetAddress host) throws WebViewException {
        try {
            return HttpServer.create(new InetSocketAddress(host, address.port()), 0);
        } catch (BindException e) {
            String why = String.valueOf(e.getMessage());
            throw new WebViewException("--web " + address + ": " + (why.contains("in use") ? "port " + address.port()
                    + " is in use on " + address.host() + " (another program, or another dolphin run, listens there)"
                    : "cannot listen there (" + why + "; is " + address.host() + " an address of this machine?)"));
        } catch (IOException e) {
            throw new WebViewException("--web " + address + ": cannot listen there: " + e.getMessage());
        }
    }

    private static String newToken() {
        byte[] bytes = new byte[16];
        new SecureRandom().nextBytes(bytes);
        return HexFormat.of().formatHex(bytes);
    }
}
