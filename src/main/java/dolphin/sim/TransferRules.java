package dolphin.sim;

/**
 * How a simulated autopilot's side of the mission protocol differs ({@link MissionItemProtocol}): when it
 * asks for an item again and gives up on an upload, what it says then, and how it answers an item it
 * did not ask for.
 *
 * @param resendNanos an item not arrived this long after it was asked for is asked for again
 * @param timeoutNanos an upload with no item for this long is cancelled
 * @param timeoutText said (WARNING) when it is
 * @param lastItemAgainAccepted the last item of a completed upload, sent again (its ACK lost), gets the ACK
 *        ACCEPTED again, rather than ERROR for an item with no upload in progress
 * @param wrongSeqIgnored an item other than the one asked for is ignored, rather than answered INVALID_SEQUENCE
 */
record TransferRules(long resendNanos, long timeoutNanos, String timeoutText, boolean lastItemAgainAccepted,
                     boolean wrongSeqIgnored) {

    /** ArduPilot's MissionItemProtocol: 1 s, 8 s, "Mission upload timeout". */
    static final TransferRules ARDUPILOT = new TransferRules(1_000_000_000L, 8_000_000_000L, "Mission upload timeout", false,
            false);
    /**
     * PX4's MavlinkMissionManager: MAVLINK_MISSION_RETRY_TIMEOUT_DEFAULT 250 ms,
     * MAVLINK_MISSION_PROTOCOL_TIMEOUT_DEFAULT 5 s, "Operation timeout".
     */
    static final TransferRules PX4 = new TransferRules(250_000_000L, 5_000_000_000L, "Operation timeout", true, true);
}
