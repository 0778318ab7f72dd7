package dolphin.mavlink

/**
 * One vehicle's datagrams copied to several ground-station ports, as a router on a vehicle with a
 * radio and an LTE modem does: each port gets every datagram from its own socket, and what comes
 * back on any of them goes to the vehicle. A path can be cut, in both directions.
 */
class DatagramRelay implements AutoCloseable {

    /** Where the vehicle sends. */
    final DatagramSocket vehicleSide = new DatagramSocket(0, InetAddress.loopbackAddress)
    final List<DatagramSocket> paths
    final List<InetSocketAddress> grounds
    final Set<Integer> cut = Collections.synchronizedSet(new HashSet<Integer>())
    private volatile SocketAddress vehicle
    private volatile boolean open = true
    private final List<Thread> threads = []

    DatagramRelay(List<InetSocketAddress> grounds) {
        this.grounds = grounds
        paths = grounds.collect { new DatagramSocket(0, InetAddress.loopbackAddress) }
        threads << Thread.start('relay from the vehicle') {
            pump(vehicleSide) { DatagramPacket p ->
                vehicle = p.socketAddress
                paths.eachWithIndex { DatagramSocket s, int i ->
                    if (!cut.contains(i)) {
                        s.send(new DatagramPacket(p.data, p.offset, p.length, grounds[i]))
                    }
                }
            }
        }
        paths.eachWithIndex { DatagramSocket s, int i ->
            threads << Thread.start("relay from ground ${i}") {
                pump(s) { DatagramPacket p ->
                    if (!cut.contains(i) && vehicle != null) {
                        vehicleSide.send(new DatagramPacket(p.data, p.offset, p.length, vehicle))
                    }
                }
            }
        }
    }

    InetSocketAddress address() {
        new InetSocketAddress(InetAddress.loopbackAddress, vehicleSide.localPort)
    }

    private void pump(DatagramSocket socket, Closure forward) {
        socket.soTimeout = 100
        byte[] buffer = new byte[65535]
        while (open) {
            def p = new DatagramPacket(buffer, buffer.length)
            try {
                socket.receive(p)
                forward(p)
            } catch (SocketTimeoutException ignored) {
            } catch (IOException e) {
                if (open) {
                    throw e
                }
            }
        }
    }

    @Override
    void close() {
        open = false
        threads*.join(2000)
        ([vehicleSide] + paths)*.close()
    }
}
