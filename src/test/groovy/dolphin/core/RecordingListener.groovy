package dolphin.core

/** Keeps every message and task event the runtime reports. */
class RecordingListener implements RuntimeListener {
    final List<String> messages = [].asSynchronized()
    final List<TaskEvent> events = [].asSynchronized()

    @Override
    void message(String text) { messages << text }

    @Override
    void taskEvent(TaskEvent event) { events << event }
}
