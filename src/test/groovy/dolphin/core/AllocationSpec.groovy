package dolphin.core

import dolphin.testing.FlyTask
import dolphin.testing.TestPlatform
import spock.lang.Specification
import spock.lang.Timeout
import spock.lang.Unroll

/**
 * Reference A.4, one row per row of the allocation table, plus the E-3 fix: allocation is per
 * occurrence, a tree mirroring the task tree, so one task object used twice runs on two vehicles.
 *
 * <p>Vehicles: '1' and '2' are UAVs, '3' is a UGV, in that platform order. Each row lists, for every
 * platform-task occurrence in tree order, the vehicles it got, and the pool left afterwards.
 * (Closures whose body is a bare {@code x >> y} use {@code return}, or Spock would read the
 * statement as a mock interaction.)
 */
@Timeout(30)
class AllocationSpec extends Specification {

    /** The reference leaves the pool after some failures unspecified (the whole execute aborts). */
    static final String UNSPECIFIED = 'unspecified'

    /** The tasks the rows build trees from. */
    static class Kit {
        final Driver d = new Driver(0)
        final Journal journal = new Journal()
        final Probe a, b, c, ugv, pair, twoUgvs

        Kit() {
            d.platform.addNode('1', 'UAV')
            d.platform.addNode('2', 'UAV')
            d.platform.addNode('3', 'UGV')
            a = Probe.lasting(journal, 'a', 1)
            b = Probe.lasting(journal, 'b', 1)
            c = Probe.lasting(journal, 'c', 1)
            ugv = Probe.requiring(journal, 'ugv', [new NodeFilter(null, 'UGV', [], null)])
            pair = Probe.requiring(journal, 'pair', [NodeFilter.ANY, NodeFilter.ANY])
            twoUgvs = Probe.requiring(journal, 'twoUgvs', [new NodeFilter(null, 'UGV', [], null), new NodeFilter(null, 'UGV', [], null)])
        }

        NodeSet set(String... ids) { d.set(ids) }

        TaskGuard always(Task t) { new TaskGuard({ true } as Condition, t) }

        Task oneOf(Task... ts) { new ChoiceTask(ts.collect { always(it) }) }

        Task allOf(Task... ts) { new AllOfTask(ts.collect { always(it) }) }

        Task watch(Task t) { new WatcherTask(t, { ErrorHandler.Decision.IGNORE } as ErrorHandler) }
    }

    @Unroll
    def "#rule: #tree"() {
        given:
        def kit = new Kit()
        Task task = build.call(kit)
        def available = kit.d.all()
        def allocation = new Allocation()

        when:
        boolean ok = task.allocate(available, allocation)

        then:
        ok == expectOk
        left == UNSPECIFIED || available.toString() == left

        when:
        if (ok) {
            task.executor.initialize(kit.d.context, allocation)
        }

        then:
        kit.journal.allocations() == vehicles

        where:
        rule                                      | tree                          | build                                                   || expectOk | vehicles                                     | left
        'platform task: first node'               | 'a'                           | { Kit k -> k.a }                                        || true     | ['a:1']                                      | '{ 2 3 }'
        'platform task: first matching node'      | 'ugv'                         | { Kit k -> k.ugv }                                      || true     | ['ugv:3']                                    | '{ 1 2 }'
        'platform task: one node per requirement' | 'pair'                        | { Kit k -> k.pair }                                     || true     | ['pair:1,2']                                 | '{ 3 }'
        'platform task: all or nothing'           | 'twoUgvs'                     | { Kit k -> k.twoUgvs }                                  || false    | []                                           | '{ 1 2 3 }'
        'sequence: separate copies'               | 'a >> b'                      | { Kit k -> return k.a >> k.b }                                 || true     | ['a:1', 'b:1']                               | '{ 2 3 }'
        'sequence: what either used is removed'   | 'a >> pair'                   | { Kit k -> return k.a >> k.pair }                              || true     | ['a:1', 'pair:1,2']                          | '{ 3 }'
        'sequence: what either used is removed'   | 'ugv >> a'                    | { Kit k -> return k.ugv >> k.a }                               || true     | ['ugv:3', 'a:1']                             | '{ 2 }'
        'sequence: one part fails'                | 'a >> twoUgvs'                | { Kit k -> return k.a >> k.twoUgvs }                           || false    | []                                           | UNSPECIFIED
        'concurrent: same pool'                   | 'a | b'                       | { Kit k -> k.a | k.b }                                  || true     | ['a:1', 'b:2']                               | '{ 3 }'
        'concurrent: same pool'                   | 'a | b | c'                   | { Kit k -> k.a | k.b | k.c }                            || true     | ['a:1', 'b:2', 'c:3']                        | '{ }'
        'concurrent: distinct vehicles'           | 'pair | ugv'                  | { Kit k -> k.pair | k.ugv }                             || true     | ['pair:1,2', 'ugv:3']                        | '{ }'
        'concurrent: too few vehicles'            | 'pair | a | b'                | { Kit k -> k.pair | k.a | k.b }                         || false    | []                                           | '{ }'
        'resource explicit: from available ∩ v'   | 'a[{ 2 3 }]'                  | { Kit k -> k.a[k.set('2', '3')] }                       || true     | ['a:2']                                      | '{ 1 3 }'
        'resource explicit: (available - v) + left' | 'a[{ 1 2 }]'                | { Kit k -> k.a[k.set('1', '2')] }                       || true     | ['a:1']                                      | '{ 3 2 }'
        'resource explicit: next takes outside v' | 'a[{ 1 2 }] | b'              | { Kit k -> k.a[k.set('1', '2')] | k.b }                 || true     | ['a:1', 'b:3']                               | '{ 2 }'
        'resource explicit: nothing usable'       | 'ugv[{ 1 2 }]'                | { Kit k -> k.ugv[k.set('1', '2')] }                     || false    | []                                           | '{ 1 2 3 }'
        'waitFor'                                 | 'waitFor then a'              | { Kit k -> new ChoiceTask([k.always(k.a)]) }            || true     | ['a:1']                                      | '{ 2 3 }'
        'oneOf: each branch from its own copy'    | 'oneOf(a, b)'                 | { Kit k -> k.oneOf(k.a, k.b) }                          || true     | ['a:1', 'b:1']                               | '{ 2 3 }'
        'oneOf: all branches\' vehicles taken'    | 'oneOf(a[{ 2 }], b, ugv)'     | { Kit k -> k.oneOf(k.a[k.set('2')], k.b, k.ugv) }       || true     | ['a:2', 'b:1', 'ugv:3']                      | '{ }'
        'allOf: each branch from its own copy'    | 'allOf(a, pair)'              | { Kit k -> k.allOf(k.a, k.pair) }                       || true     | ['a:1', 'pair:1,2']                          | '{ 3 }'
        'allOf: a branch fails'                   | 'allOf(a, twoUgvs)'           | { Kit k -> k.allOf(k.a, k.twoUgvs) }                    || false    | []                                           | UNSPECIFIED
        'constrained delegates'                   | 'a / { c }'                   | { Kit k -> k.a / ({ false } as Condition) }             || true     | ['a:1']                                      | '{ 2 3 }'
        'during delegates'                        | 'during 5 run pair'           | { Kit k -> new TimeConstrainedTask(k.pair, 5) }         || true     | ['pair:1,2']                                 | '{ 3 }'
        'watcher delegates'                       | 'watch ugv'                   | { Kit k -> k.watch(k.ugv) }                             || true     | ['ugv:3']                                    | '{ 1 2 }'
        'idle uses no vehicle'                    | 'idle 1'                      | { Kit k -> new IdleTask(1) }                            || true     | []                                           | '{ 1 2 3 }'
        'action uses no vehicle'                  | 'action'                      | { Kit k -> new ActionTask({} as Runnable) }             || true     | []                                           | '{ 1 2 3 }'
        'condition uses no vehicle'               | 'condition'                   | { Kit k -> new ConditionTask({ true } as Condition) }   || true     | []                                           | '{ 1 2 3 }'
        'local tasks beside a platform task'      | 'idle 1 | a | action'         | { Kit k -> new IdleTask(1) | k.a | new ActionTask({} as Runnable) } || true | ['a:1']                        | '{ 2 3 }'
        'E-3: one object in both branches of |'   | 'a | a'                       | { Kit k -> k.a | k.a }                                  || true     | ['a:1', 'a:2']                               | '{ 3 }'
        'E-3: one object three times'             | 'a | a | a'                   | { Kit k -> k.a | k.a | k.a }                            || true     | ['a:1', 'a:2', 'a:3']                        | '{ }'
        'E-3: one object in a sequence'           | 'a >> a'                      | { Kit k -> return k.a >> k.a }                                 || true     | ['a:1', 'a:1']                               | '{ 2 3 }'
        'E-3: reused across operators'            | '(a | a) >> (a | b | a)'      | { Kit k -> (k.a | k.a) >> (k.a | k.b | k.a) }           || true     | ['a:1', 'a:2', 'a:1', 'b:2', 'a:3']          | '{ }'
        'E-3: one object on explicit sets'        | 'a[{ 3 }] | a[{ 2 }]'         | { Kit k -> k.a[k.set('3')] | k.a[k.set('2')] }          || true     | ['a:3', 'a:2']                               | '{ 1 }'
        'E-3: one object in two guarded branches' | 'oneOf(a, a[{ 2 }])'          | { Kit k -> k.oneOf(k.a, k.a[k.set('2')]) }              || true     | ['a:1', 'a:2']                               | '{ 3 }'
    }

    def "the allocation is a tree mirroring the task tree"() {
        given:
        def kit = new Kit()
        def allocation = new Allocation()
        def task = (kit.a | kit.b) >> kit.ugv[kit.set('3')]

        when:
        task.allocate(kit.d.all(), allocation)

        then:
        allocation.nodes().empty
        allocation.child(0).child(0).nodes()*.id == ['1']
        allocation.child(0).child(1).nodes()*.id == ['2']
        allocation.child(1).nodes()*.id == ['3']
        allocation.allNodes()*.id == ['1', '2', '3']
    }

    def "a failed allocation says which task found no vehicle"() {
        given:
        def kit = new Kit()
        def allocation = new Allocation()

        when:
        def ok = (kit.a | kit.twoUgvs).allocate(kit.d.all(), allocation)

        then:
        !ok
        allocation.failure().contains("'twoUgvs'")
        allocation.failure().contains('UGV')
    }

    def "E-3: one task object used in both branches of | runs on two vehicles"() {
        given:
        def clock = ManualClock.autoAdvancing()
        def platform = new TestPlatform()
        ['1', '2'].each { platform.addNode(it) }
        def env = new Environment(platform, clock, new RecordingListener())
        env.select(NodeFilter.ANY, 2, 0)
        def returnHome = new FlyTask(platform, 'returnHome', 1)

        when:
        def cs = env.run(returnHome | returnHome)

        then:
        cs == CompletionState.DONE
        platform.journal*.toString() as Set == ['start returnHome 1 @0.0', 'start returnHome 2 @0.0',
                                                'done returnHome 1 @1.0', 'done returnHome 2 @1.0'] as Set
    }

    def "E-3: one task object at two places of a sequence runs on the vehicle of each occurrence"() {
        given:
        def clock = ManualClock.autoAdvancing()
        def platform = new TestPlatform()
        ['1', '2', '3'].each { platform.addNode(it) }
        def env = new Environment(platform, clock, new RecordingListener())
        env.select(NodeFilter.ANY, 3, 0)
        def survey = new FlyTask(platform, 'survey', 1)
        def home = new FlyTask(platform, 'home', 1)
        def v1 = NodeSet.of(platform.node('1'))
        def v3 = NodeSet.of(platform.node('3'))

        when:
        env.run(survey[v1] >> home[v1] | survey[v3] >> home[v3])

        then:
        platform.journal.findAll { it.kind == 'start' }*.toString() == [
                'start survey 1 @0.0', 'start survey 3 @0.0', 'start home 1 @1.0', 'start home 3 @1.0']
    }
}
