package dolphin.web

import spock.lang.Specification

class EventLogSpec extends Specification {

    def "entries are numbered; a viewer gets what came after its last, and is told how many it can no longer get"() {
        given:
        def log = new EventLog(3)

        when:
        (1..5).each { log.add(it, 'message', null, "line ${it}") }

        then:
        log.last() == 5
        log.since(0).entries()*.text == ['line 3', 'line 4', 'line 5']
        log.since(0).lost() == 2
        log.since(3).entries()*.seq == [4, 5]
        log.since(3).lost() == 0
        log.since(5).entries().isEmpty()
        log.since(5).lost() == 0
    }

    def "a vehicle's line names the vehicle"() {
        given:
        def log = new EventLog(10)
        log.add(1.5, 'vehicle', '2', 'PreArm: Need Position Estimate')

        expect:
        log.since(0).entries()[0] == new EventLog.Entry(1, 1.5, 'vehicle', '2', 'PreArm: Need Position Estimate')
    }
}
