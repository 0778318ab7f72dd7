package dolphin.mission.survey;

/**
 * Which QGroundControl generation of item emission to copy (docs/qgc-surveys.md §2.8). They differ
 * only in where the camera trigger commands go and in the stop command's param3.
 */
public enum Emission {
    /**
     * Generation C, current QGC: the trigger restarted at every entry, stops with param3 1;
     * corridors relabel their reversed transects.
     */
    CURRENT,
    /** Generation A, the QGC 3.x survey builder: one start and one stop with images in turnarounds, stop param3 0. */
    LEGACY_SURVEY,
    /** Generation B, the old corridor builder. */
    LEGACY_CORRIDOR,
    /**
     * Generation C from the intermediate release that did not swap entry and exit on a corridor's
     * reversed transects (§3.1), so the trigger starts at the far end of those; surveys emit as {@link #CURRENT}.
     */
    CURRENT_NO_LABEL_SWAP
}
