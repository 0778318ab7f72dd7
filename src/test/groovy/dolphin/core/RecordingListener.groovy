package dolphin.core

/** Keeps every message and task event the runtime reports. */
class RecordingListener implements RuntimeListener {
    final List<String> messages = new java.util.concurrent.CopyOnWriteArrayList()
    final List<TaskEvent> events = new java.util.concurrent.CopyOnWriteArrayList()

    @Override
    void message(String text) { messages << text }

    @Override
    void taskEvent(TaskEvent event) { events << event }
}
