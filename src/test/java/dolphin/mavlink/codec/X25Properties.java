package dolphin.mavlink.codec;

import static org.junit.jupiter.api.Assertions.assertEquals;

import java.nio.charset.StandardCharsets;
import net.jqwik.api.Example;
import net.jqwik.api.ForAll;
import net.jqwik.api.Property;
import net.jqwik.api.constraints.IntRange;
import net.jqwik.api.constraints.Size;

/** The table-driven checksum of a run of bytes equals the byte-at-a-time definition. */
class X25Properties {

    @Property(tries = 2000)
    void runEqualsByteAtATime(@ForAll @Size(max = 300) byte[] bytes, @ForAll @IntRange(max = 0xFFFF) int seed,
                              @ForAll @IntRange(max = 300) int from, @ForAll @IntRange(max = 300) int to) {
        int off = Math.min(from, bytes.length);
        int end = Math.max(off, Math.min(to, bytes.length));
        int expected = seed;
        for (int i = off; i < end; i++) {
            expected = X25.accumulate(expected, bytes[i]);
        }
        assertEquals(expected, X25.accumulate(seed, bytes, off, end - off));
    }

    @Example
    void knownCheckValue() {
        // The catalogued check value of CRC-16/MCRF4XX: the checksum of "123456789".
        assertEquals(0x6F91, X25.accumulate(X25.SEED, "123456789".getBytes(StandardCharsets.US_ASCII), 0, 9));
    }
}
