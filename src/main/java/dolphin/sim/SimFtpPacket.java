package dolphin.sim;

import com.MAVLink.common.msg_file_transfer_protocol;
import java.nio.charset.StandardCharsets;
import java.util.Arrays;

/**
 * One MAVLink FTP request or reply as ArduPilot's GCS_FTP keeps it (its Transaction): the
 * FILE_TRANSFER_PROTOCOL payload's header (seq u16 LE, session, opcode, size, req_opcode,
 * burst_complete, offset u32 LE) and its 239 data bytes, with the requester's system and component.
 */
record SimFtpPacket(int sysid, int compid, int seq, int session, int opcode, int size, int reqOpcode,
                    boolean burstComplete, long offset, byte[] data) {

    static final int DATA_BYTES = 239;

    static final int NONE = 0;
    static final int TERMINATE_SESSION = 1;
    static final int RESET_SESSIONS = 2;
    static final int LIST_DIRECTORY = 3;
    static final int OPEN_FILE_RO = 4;
    static final int READ_FILE = 5;
    static final int CREATE_FILE = 6;
    static final int WRITE_FILE = 7;
    static final int REMOVE_FILE = 8;
    static final int CREATE_DIRECTORY = 9;
    static final int REMOVE_DIRECTORY = 10;
    static final int OPEN_FILE_WO = 11;
    static final int RENAME = 13;
    static final int CALC_FILE_CRC32 = 14;
    static final int BURST_READ_FILE = 15;
    static final int ACK = 128;
    static final int NAK = 129;

    /** MAV_FTP_ERR, the first data byte of a NAK. */
    static final int FAIL = 1;
    static final int FAIL_ERRNO = 2;
    static final int INVALID_DATA_SIZE = 3;
    static final int NO_SESSIONS_AVAILABLE = 5;
    static final int EOF = 6;
    static final int FILE_EXISTS = 8;
    static final int FILE_NOT_FOUND = 10;

    /** The errno values the simulated filesystem sets. */
    static final int ENOENT = 2;
    static final int EBADF = 9;
    static final int EBUSY = 16;
    static final int EEXIST = 17;
    static final int EINVAL = 22;
    static final int ENFILE = 23;
    static final int ENOSPC = 28;

    /** The request a FILE_TRANSFER_PROTOCOL message carries. */
    static SimFtpPacket of(msg_file_transfer_protocol m) {
        byte[] p = new byte[m.payload.length];
        for (int i = 0; i < p.length; i++) {
            p[i] = (byte) m.payload[i];
        }
        return new SimFtpPacket(m.sysid, m.compid, u8(p, 0) | u8(p, 1) << 8, u8(p, 2), u8(p, 3), u8(p, 4), u8(p, 5),
                u8(p, 6) != 0, u8(p, 8) | u8(p, 9) << 8 | u8(p, 10) << 16 | (long) u8(p, 11) << 24,
                Arrays.copyOfRange(p, 12, 12 + DATA_BYTES));
    }

    /** GCS_FTP::setup_reply: to the requester, same session, seq + 1, req_opcode the request's, all else zero. */
    SimFtpPacket reply() {
        return new SimFtpPacket(sysid, compid, (seq + 1) & 0xffff, session, NONE, 0, opcode, false, 0, new byte[DATA_BYTES]);
    }

    SimFtpPacket ack(int size, byte[] bytes, long at) {
        byte[] d = new byte[DATA_BYTES];
        System.arraycopy(bytes, 0, d, 0, Math.min(bytes.length, DATA_BYTES));
        return new SimFtpPacket(sysid, compid, seq, session, ACK, size, reqOpcode, burstComplete, at, d);
    }

    /** GCS_FTP::error: a NAK with the error (and, for FAIL_ERRNO, the errno; ENOENT and EEXIST have codes of their own). */
    SimFtpPacket nak(int error, int errno) {
        byte[] d = data.clone();
        int size = 1;
        d[0] = (byte) error;
        if (error == FAIL_ERRNO) {
            if (errno == ENOENT) {
                d[0] = (byte) FILE_NOT_FOUND;
            } else if (errno == EEXIST) {
                d[0] = (byte) FILE_EXISTS;
            } else {
                d[1] = (byte) errno;
                size = 2;
            }
        }
        return new SimFtpPacket(sysid, compid, seq, session, NAK, size, reqOpcode, burstComplete, offset, d);
    }

    SimFtpPacket nak(int error) {
        return nak(error, 0);
    }

    /** The same with no data, as a burst's reply after a read that gave nothing. */
    SimFtpPacket cleared() {
        return new SimFtpPacket(sysid, compid, seq, session, opcode, size, reqOpcode, burstComplete, offset, new byte[DATA_BYTES]);
    }

    SimFtpPacket withSeq(int s) {
        return new SimFtpPacket(sysid, compid, s & 0xffff, session, opcode, size, reqOpcode, burstComplete, offset, data);
    }

    SimFtpPacket withOffset(long at) {
        return new SimFtpPacket(sysid, compid, seq, session, opcode, size, reqOpcode, burstComplete, at, data);
    }

    SimFtpPacket withBurstComplete(boolean complete) {
        return new SimFtpPacket(sysid, compid, seq, session, opcode, size, reqOpcode, complete, offset, data);
    }

    /** The path a request names: its data up to the first NUL. */
    String path() {
        int n = 0;
        while (n < DATA_BYTES - 1 && data[n] != 0) {
            n++;
        }
        return new String(data, 0, n, StandardCharsets.ISO_8859_1);
    }

    /** GCS_FTP::Session::check_name_len: size is the name's length, or one more with the last data byte NUL. */
    boolean nameLengthValid() {
        int length = 0;
        while (length < DATA_BYTES && data[length] != 0) {
            length++;
        }
        if (size == 0) {
            return false;
        }
        return length == size || (size - length == 1 && data[DATA_BYTES - 1] == 0);
    }

    /** As the vehicle sends it. */
    msg_file_transfer_protocol toMessage() {
        msg_file_transfer_protocol m = new msg_file_transfer_protocol();
        m.target_network = 0;
        m.target_system = (short) sysid;
        m.target_component = (short) compid;
        short[] p = m.payload;
        p[0] = (short) (seq & 0xff);
        p[1] = (short) (seq >> 8 & 0xff);
        p[2] = (short) session;
        p[3] = (short) opcode;
        p[4] = (short) size;
        p[5] = (short) reqOpcode;
        p[6] = (short) (burstComplete ? 1 : 0);
        for (int i = 0; i < 4; i++) {
            p[8 + i] = (short) (offset >> (8 * i) & 0xff);
        }
        for (int i = 0; i < DATA_BYTES; i++) {
            p[12 + i] = (short) (data[i] & 0xff);
        }
        return m;
    }

    private static int u8(byte[] p, int i) {
        return p[i] & 0xff;
    }
}
