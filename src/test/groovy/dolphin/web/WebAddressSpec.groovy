package dolphin.web

import spock.lang.Specification

class WebAddressSpec extends Specification {

    def "#text listens on #host port #port"() {
        expect:
        WebAddress.parse(text) == new WebAddress(host, port)

        where:
        text             || host          | port
        '8080'           || '127.0.0.1'   | 8080
        '0'              || '127.0.0.1'   | 0
        '0.0.0.0:8080'   || '0.0.0.0'     | 8080
        'localhost:9000' || 'localhost'   | 9000
        '[::1]:8080'     || '::1'         | 8080
    }

    def "'#text' is refused: #message"() {
        when:
        WebAddress.parse(text)

        then:
        def e = thrown(IllegalArgumentException)
        e.message.contains(message)

        where:
        text          || message
        'web'         || "expected [HOST:]PORT, e.g. 8080 or 0.0.0.0:8080"
        'host:'       || 'expected [HOST:]PORT'
        '70000'       || 'the port must be between 0 and 65535, got 70000'
        ':8080'       || 'the host is empty'
        '::1:8080'    || 'write an IPv6 host in brackets, e.g. [::1]:8080'
    }

    def "the Host header's name, token and cookie are read as browsers send them"() {
        expect:
        Access.hostName('127.0.0.1:8080') == '127.0.0.1'
        Access.hostName('LocalHost') == 'localhost'
        Access.hostName('[::1]:8080') == '[::1]'
        Access.hostName(null) == ''
        Access.queryToken('a=1&token=abc') == 'abc'
        Access.queryToken(null) == null
        Access.cookieToken('x=1; dolphin-token=abc') == 'abc'
    }
}
