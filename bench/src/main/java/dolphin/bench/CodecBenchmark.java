package dolphin.bench;

import com.MAVLink.Messages.MAVLinkMessage;
import dolphin.mavlink.codec.DropCounters;
import dolphin.mavlink.codec.Frame;
import dolphin.mavlink.codec.FrameReader;
import dolphin.mavlink.codec.FrameWriter;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import org.openjdk.jmh.annotations.Benchmark;
import org.openjdk.jmh.annotations.BenchmarkMode;
import org.openjdk.jmh.annotations.Fork;
import org.openjdk.jmh.annotations.Level;
import org.openjdk.jmh.annotations.Measurement;
import org.openjdk.jmh.annotations.Mode;
import org.openjdk.jmh.annotations.OperationsPerInvocation;
import org.openjdk.jmh.annotations.OutputTimeUnit;
import org.openjdk.jmh.annotations.Param;
import org.openjdk.jmh.annotations.Scope;
import org.openjdk.jmh.annotations.Setup;
import org.openjdk.jmh.annotations.State;
import org.openjdk.jmh.annotations.TearDown;
import org.openjdk.jmh.annotations.Warmup;
import org.openjdk.jmh.infra.Blackhole;

/**
 * Throughput of the frame codec on one thread, in frames per second (one JMH operation is one
 * frame): {@link FrameReader} over the {@link MixedStream} of {@value #FRAMES} frames, alone
 * ("framing") and followed by {@link Frame#message()} on every frame ("decode"), with the bytes
 * fed as a stream (chunks of {@code chunk} bytes, frames split across chunks, as a serial port or
 * TCP read delivers them) or as datagrams (one frame per datagram, fed then ended with
 * {@link FrameReader#endOfPacket}, as a UDP link delivers them); and {@link FrameWriter#write} of
 * the same messages. Every iteration checks that every frame came out and none was dropped.
 */
@State(Scope.Thread)
@BenchmarkMode(Mode.Throughput)
@OutputTimeUnit(TimeUnit.SECONDS)
@Fork(value = 1, jvmArgsAppend = {"-Xms512m", "-Xmx512m"})
@Warmup(iterations = 3, time = 1)
@Measurement(iterations = 5, time = 1)
public class CodecBenchmark {

    public static final int FRAMES = 10_000;

    /** The stream MixedStream wrote (so both sides parse the same bytes); empty: generate it here. */
    @Param({""})
    public String file;

    /** Bytes per feed() in the stream benchmarks. */
    @Param({"4096"})
    public int chunk;

    private byte[] stream;
    private int[] bounds;
    private List<MAVLinkMessage> messages;
    private FrameReader reader;
    private long frames;
    private long invocations;

    @Setup(Level.Trial)
    public void load() {
        try {
            stream = file.isEmpty() ? MixedStream.concat(MixedStream.frames(FRAMES, MixedStream.SEED)) : Files.readAllBytes(Path.of(file));
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        bounds = MixedStream.boundaries(stream);
        if (bounds.length - 1 != FRAMES) {
            throw new IllegalStateException("the stream has " + (bounds.length - 1) + " frames, the benchmark counts " + FRAMES);
        }
        messages = MixedStream.messages(FRAMES, MixedStream.SEED);
        reader = new FrameReader();
    }

    @Setup(Level.Iteration)
    public void resetCounts() {
        frames = 0;
        invocations = 0;
    }

    @TearDown(Level.Iteration)
    public void check() {
        DropCounters drops = reader.drops();
        if (frames != invocations * FRAMES || drops.frames() != 0 || drops.get(DropCounters.Reason.GARBAGE_BYTES) != 0) {
            throw new IllegalStateException("expected " + invocations * FRAMES + " frames, got " + frames + "; drops " + drops);
        }
    }

    private void stream(Consumer<Frame> sink) {
        invocations++;
        byte[] s = stream;
        for (int off = 0; off < s.length; off += chunk) {
            reader.feed(s, off, Math.min(chunk, s.length - off), sink);
        }
    }

    private void datagrams(Consumer<Frame> sink) {
        invocations++;
        int[] b = bounds;
        for (int i = 0; i < FRAMES; i++) {
            reader.feed(stream, b[i], b[i + 1] - b[i], sink);
            reader.endOfPacket(sink);
        }
    }

    @Benchmark
    @OperationsPerInvocation(FRAMES)
    public void framingStream(Blackhole bh) {
        stream(f -> {
            frames++;
            bh.consume(f);
        });
    }

    @Benchmark
    @OperationsPerInvocation(FRAMES)
    public void framingDatagrams(Blackhole bh) {
        datagrams(f -> {
            frames++;
            bh.consume(f);
        });
    }

    @Benchmark
    @OperationsPerInvocation(FRAMES)
    public void decodeStream(Blackhole bh) {
        stream(f -> {
            frames++;
            bh.consume(f.message());
        });
    }

    @Benchmark
    @OperationsPerInvocation(FRAMES)
    public void decodeDatagrams(Blackhole bh) {
        datagrams(f -> {
            frames++;
            bh.consume(f.message());
        });
    }

    /** FrameWriter.write of the stream's messages (three senders, as in the stream). */
    @Benchmark
    @OperationsPerInvocation(FRAMES)
    public void write(WriterState w, Blackhole bh) {
        for (MAVLinkMessage m : messages) {
            bh.consume(w.writers[m.sysid - 1].write(m));
        }
    }

    @State(Scope.Thread)
    public static class WriterState {
        final FrameWriter[] writers = {new FrameWriter(1, 1), new FrameWriter(2, 1), new FrameWriter(3, 1)};
    }
}
