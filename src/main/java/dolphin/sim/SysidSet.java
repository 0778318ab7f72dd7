package dolphin.sim;

import java.util.Collection;
import java.util.Set;
import java.util.TreeSet;

/** Which vehicles of a fleet, by system id: every one, or those listed. */
public record SysidSet(boolean all, Set<Integer> ids) {

    public static final SysidSet ALL = new SysidSet(true, Set.of());
    public static final SysidSet NONE = new SysidSet(false, Set.of());

    public SysidSet {
        ids = Set.copyOf(ids);
        if (all && !ids.isEmpty()) {
            throw new IllegalArgumentException("every vehicle, or those listed, not both: " + ids);
        }
        for (int id : ids) {
            if (id < 1 || id > 255) {
                throw new IllegalArgumentException("a system id must lie in 1..255, got " + id);
            }
        }
    }

    public static SysidSet of(Collection<Integer> ids) {
        return new SysidSet(false, Set.copyOf(ids));
    }

    public boolean contains(int sysid) {
        return all || ids.contains(sysid);
    }

    public SysidSet union(SysidSet other) {
        if (all || other.all) {
            return ALL;
        }
        Set<Integer> both = new TreeSet<>(ids);
        both.addAll(other.ids);
        return of(both);
    }

    /** The listed ids outside {@code first..last}, lowest first. */
    public Set<Integer> outside(int first, int last) {
        Set<Integer> out = new TreeSet<>(ids);
        out.removeIf(id -> id >= first && id <= last);
        return out;
    }

    @Override
    public String toString() {
        return all ? "all" : new TreeSet<>(ids).toString();
    }
}
