package dolphin.sim;

import com.MAVLink.enums.MAV_MISSION_RESULT;
import dolphin.mission.model.MissionItem;
import dolphin.mission.model.MissionType;
import dolphin.mission.transfer.MissionFtpFile;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.util.List;
import java.util.function.Function;

/**
 * Stores a @MISSION file written over MAVLink FTP, as AP_Filesystem_Mission::finish_upload does when
 * it is closed: the header's magic, a count that matches the length, no all-zero item (a write that
 * never arrived), then each item checked as the mission protocol checks it. A mission is cleared
 * first (unless options bit 0, NO_CLEAR, or while flying it in AUTO, when ArduPilot's clear fails and
 * is ignored), then stored item by item from the header's start, so a refused item leaves those
 * before it; a DO_JUMP to item 0 or past the count is refused. A fence is checked whole and replaces
 * the old one only when valid; rally points are cleared, then appended until one is refused. Fence
 * and rally refuse NO_CLEAR. Nothing is said: the mission protocol's "Flight plan received" is not
 * sent for a file.
 */
final class MissionFileLoader {

    private static final int NO_CLEAR = 1;

    private final Function<MissionType, ItemStore> stores;
    private final MissionItemProtocol.Host host;

    MissionFileLoader(Function<MissionType, ItemStore> stores, MissionItemProtocol.Host host) {
        this.stores = stores;
        this.host = host;
    }

    /** Whether the file was stored whole; {@code type} is the file's (its name's), whatever the header says. */
    boolean load(MissionType type, byte[] file) {
        if (file.length < MissionFtpFile.HEADER_BYTES) {
            return false;
        }
        ByteBuffer b = ByteBuffer.wrap(file).order(ByteOrder.LITTLE_ENDIAN);
        int items = (file.length - MissionFtpFile.HEADER_BYTES) / MissionFtpFile.ITEM_BYTES;
        if (Short.toUnsignedInt(b.getShort(0)) != MissionFtpFile.MAGIC || Short.toUnsignedInt(b.getShort(8)) != items) {
            return false;
        }
        for (int i = 0; i < items; i++) {
            if (allZero(file, MissionFtpFile.HEADER_BYTES + i * MissionFtpFile.ITEM_BYTES)) {
                return false;
            }
        }
        // the name says which list; decode reads the type from the header, so it is set to the name's
        byte[] named = file.clone();
        ByteBuffer.wrap(named).order(ByteOrder.LITTLE_ENDIAN).putShort(2, (short) type.wire());
        MissionFtpFile.Contents contents = MissionFtpFile.decode(named);
        boolean stored = switch (type) {
            case MISSION -> mission(contents);
            case FENCE -> fence(contents);
            case RALLY -> rally(contents);
        };
        host.changed(type);
        return stored;
    }

    private boolean mission(MissionFtpFile.Contents contents) {
        ItemStore store = stores.apply(MissionType.MISSION);
        if ((contents.options() & NO_CLEAR) == 0 && host.clearAllowed()) {
            store.clear();
        }
        List<MissionItem> items = contents.items();
        for (MissionItem item : items) {
            if (store.check(item) != MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED || MissionCheck.jumpsNowhere(item, items.size())
                    || item.seq() > store.count() || item.seq() >= store.capacity()) {
                return false;
            }
            store.put(item);
        }
        return true;
    }

    private boolean fence(MissionFtpFile.Contents contents) {
        ItemStore store = stores.apply(MissionType.FENCE);
        if ((contents.options() & NO_CLEAR) != 0) {
            return false;
        }
        for (MissionItem item : contents.items()) {
            if (store.check(item) != MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED) {
                return false;
            }
        }
        store.truncate(contents.items().size());
        contents.items().forEach(store::put);
        return store.complete() == MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED;
    }

    private boolean rally(MissionFtpFile.Contents contents) {
        ItemStore store = stores.apply(MissionType.RALLY);
        if ((contents.options() & NO_CLEAR) != 0) {
            return false;
        }
        store.truncate(0);
        for (MissionItem item : contents.items()) {
            if (store.check(item) != MAV_MISSION_RESULT.MAV_MISSION_ACCEPTED) {
                return false;
            }
            store.put(item);
        }
        return true;
    }

    private static boolean allZero(byte[] file, int from) {
        for (int i = from; i < from + MissionFtpFile.ITEM_BYTES; i++) {
            if (file[i] != 0) {
                return false;
            }
        }
        return true;
    }
}
