package dolphin.sim;

import dolphin.mission.model.MissionItem;
import dolphin.mission.model.MissionType;
import dolphin.mission.transfer.MissionFtpFile;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.util.Arrays;
import java.util.List;
import java.util.function.Function;

/**
 * A simulated vehicle's files as MAVLink FTP reaches them: only ArduPilot's AP_Filesystem_Mission
 * ({@code @MISSION/mission.dat}, {@code fence.dat}, {@code rally.dat}; any other path is ENOENT). Four
 * open files at most; a file idle for 30 s is dropped when another is opened; one upload at a time
 * (another is refused with EBUSY, where ArduPilot leaves errno as it was).
 * A file read gives the header (item count as at the open) and each stored item as a download
 * reports it; a file written grows as written (sized from its header when that comes at offset 0,
 * zero-filled) and is loaded into the lists when closed ({@link MissionFileLoader}). Errors are
 * negative errno values.
 */
final class MissionFiles {

    /** What stat says of every @MISSION file (AP_Filesystem_Mission::stat: read to EOF instead). */
    static final int FILE_SIZE = 1024 * 1024;
    /** The most a file written may grow to here, as ArduPilot's memory runs out (ENOSPC). */
    static final int MAX_WRITTEN = 4 * FILE_SIZE;
    static final int MAX_OPEN = 4;
    static final long IDLE_NANOS = 30_000_000_000L;

    private static final class MissionFileSlot {
        MissionType type;
        int items;
        long offset;
        long lastOp;
        byte[] written;
        int length;
    }

    private final Function<MissionType, ItemStore> stores;
    private final MissionFileLoader loader;
    private final MissionFileSlot[] files = new MissionFileSlot[MAX_OPEN];

    MissionFiles(Function<MissionType, ItemStore> stores, MissionFileLoader loader) {
        this.stores = stores;
        this.loader = loader;
    }

    /** The list a path names ("@MISSION/mission.dat", a leading slash allowed), or null. */
    static MissionType typeOf(String path) {
        String p = path.startsWith("/") ? path.substring(1) : path;
        if (!p.startsWith("@MISSION")) {
            return null;
        }
        p = p.substring("@MISSION".length());
        if (p.startsWith("/")) {
            p = p.substring(1);
        }
        for (MissionType t : MissionType.values()) {
            if (MissionFtpFile.path(t).equals("@MISSION/" + p)) {
                return t;
            }
        }
        return null;
    }

    /** A file descriptor, or -errno. */
    int open(String path, boolean readOnly, long now) {
        MissionType type = typeOf(path);
        if (type == null || stores.apply(type) == null) {
            return -SimFtpPacket.ENOENT;
        }
        int fd = 0;
        for (; fd < MAX_OPEN; fd++) {
            MissionFileSlot f = files[fd];
            if (f != null && now - f.lastOp > IDLE_NANOS) {
                files[fd] = null;
                f = null;
            }
            if (!readOnly && f != null && f.written != null) {
                // one upload at a time: ArduPilot fails without setting errno, EBUSY here
                return -SimFtpPacket.EBUSY;
            }
            if (f == null) {
                break;
            }
        }
        if (fd == MAX_OPEN) {
            return -SimFtpPacket.ENFILE;
        }
        MissionFileSlot f = new MissionFileSlot();
        f.type = type;
        f.items = stores.apply(type).count();
        f.lastOp = now;
        f.written = readOnly ? null : new byte[0];
        files[fd] = f;
        return fd;
    }

    /** Up to {@code count} bytes at {@code offset}: fewer at the end, none past it; or null for a bad descriptor. */
    byte[] read(int fd, long offset, int count, long now) {
        MissionFileSlot f = file(fd);
        if (f == null || f.written != null) {
            return null;
        }
        f.lastOp = now;
        f.offset = offset;
        ByteBuffer out = ByteBuffer.allocate(count);
        if (f.offset < MissionFtpFile.HEADER_BYTES) {
            ByteBuffer header = ByteBuffer.allocate(MissionFtpFile.HEADER_BYTES).order(ByteOrder.LITTLE_ENDIAN);
            header.putShort((short) MissionFtpFile.MAGIC).putShort((short) f.type.wire()).putShort((short) 0)
                    .putShort((short) 0).putShort((short) f.items);
            int n = (int) Math.min(MissionFtpFile.HEADER_BYTES - f.offset, count);
            out.put(header.array(), (int) f.offset, n);
            f.offset += n;
            if (!out.hasRemaining()) {
                return out.array();
            }
        }
        ItemStore store = stores.apply(f.type);
        long dataOffset = f.offset - MissionFtpFile.HEADER_BYTES;
        while (out.hasRemaining()) {
            long index = dataOffset / MissionFtpFile.ITEM_BYTES;
            if (index >= store.count()) {
                break;
            }
            int within = (int) (dataOffset % MissionFtpFile.ITEM_BYTES);
            byte[] item = itemBytes(f.type, store.reported((int) index));
            int n = Math.min(MissionFtpFile.ITEM_BYTES - within, out.remaining());
            out.put(item, within, n);
            dataOffset += n;
        }
        f.offset = dataOffset + MissionFtpFile.HEADER_BYTES;
        return Arrays.copyOf(out.array(), out.position());
    }

    /** Writes at {@code offset}: 0, or -errno. */
    int write(int fd, long offset, byte[] bytes, long now) {
        MissionFileSlot f = file(fd);
        if (f == null || f.written == null) {
            return -SimFtpPacket.EBADF;
        }
        f.lastOp = now;
        int size = f.length;
        if (offset == 0 && bytes.length >= MissionFtpFile.HEADER_BYTES) {
            // the buffer is sized from the header's count, magic or not (AP_Filesystem_Mission::write)
            int items = (bytes[8] & 0xff) | (bytes[9] & 0xff) << 8;
            if (items < 0xffff) {
                size = Math.max(size, MissionFtpFile.HEADER_BYTES + items * MissionFtpFile.ITEM_BYTES);
            }
        }
        long end = offset + bytes.length;
        if (end > MAX_WRITTEN || size > MAX_WRITTEN) {
            return -SimFtpPacket.ENOSPC;
        }
        size = (int) Math.max(size, end);
        if (size > f.written.length) {
            f.written = Arrays.copyOf(f.written, size);
        }
        f.length = size;
        System.arraycopy(bytes, 0, f.written, (int) offset, bytes.length);
        return 0;
    }

    /** Closes the file; a file written is loaded into the lists: 0, or -EINVAL when refused, -EBADF for a bad descriptor. */
    int close(int fd) {
        MissionFileSlot f = file(fd);
        if (f == null) {
            return -SimFtpPacket.EBADF;
        }
        files[fd] = null;
        if (f.written != null && !loader.load(f.type, Arrays.copyOf(f.written, f.length))) {
            return -SimFtpPacket.EINVAL;
        }
        return 0;
    }

    private MissionFileSlot file(int fd) {
        return fd >= 0 && fd < MAX_OPEN ? files[fd] : null;
    }

    private static byte[] itemBytes(MissionType type, MissionItem item) {
        byte[] one = MissionFtpFile.encode(type, List.of(item));
        return Arrays.copyOfRange(one, MissionFtpFile.HEADER_BYTES, one.length);
    }
}
