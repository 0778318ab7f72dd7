package dolphin.mavlink

import java.nio.ByteBuffer
import java.nio.file.Files
import java.nio.file.Path
import spock.lang.Specification
import spock.lang.TempDir

/** The tlog on disk holds whole records at any moment, even before it is closed (a run stopped by a signal). */
class TlogSpec extends Specification {

    @TempDir
    Path dir

    def "records of a size that does not divide the buffer are never split on disk"() {
        given: '58-byte records (an 8-byte timestamp and a 50-byte frame): 8192 is no multiple of 58'
        Path file = dir.resolve('run.tlog')
        def log = new Tlog(file)
        byte[] frame = (0..<50).collect { (byte) it } as byte[]

        when: 'written, and the file read while the log is still open'
        1000.times { log.write(frame) }
        byte[] onDisk = Files.readAllBytes(file)

        then: 'some of it is on disk, as whole records each holding the frame'
        onDisk.length > 0
        onDisk.length % 58 == 0
        (0..<onDisk.length.intdiv(58)).every { int i ->
            ByteBuffer.wrap(onDisk, i * 58 + 8, 50).with { b -> (0..<50).every { b.get() == (byte) it } }
        }

        cleanup:
        log?.close()
    }

    def "closed, it holds every record, in order, with increasing timestamps"() {
        given:
        Path file = dir.resolve('all.tlog')
        def log = new Tlog(file)

        when:
        (1..3).each { log.write([it, it, it] as byte[]) }
        log.close()
        ByteBuffer b = ByteBuffer.wrap(Files.readAllBytes(file))
        def records = (1..3).collect { [b.getLong(), [b.get(), b.get(), b.get()]] }

        then:
        !b.hasRemaining()
        records*.get(1) == [[1, 1, 1], [2, 2, 2], [3, 3, 3]]
        records*.get(0) == records*.get(0).sort()
        records[0][0] > 1_600_000_000_000_000L
    }
}
