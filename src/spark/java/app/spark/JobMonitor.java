package app.spark;

import java.util.BitSet;
import java.util.HashSet;
import java.util.Set;

import org.apache.spark.Success$;
import org.apache.spark.scheduler.SparkListener;
import org.apache.spark.scheduler.SparkListenerJobStart;
import org.apache.spark.scheduler.SparkListenerTaskEnd;
import org.apache.spark.scheduler.TaskInfo;

import renderer.Progress;
import scala.jdk.javaapi.CollectionConverters;

/**
 * Watches one render job on the driver (Spark calls it on its listener thread): advances the
 * progress by a partition's tiles the first time that partition succeeds, and counts task
 * attempts, retries and the executors that ran them, for the summary line. Only the jobs of its
 * job group count, so other jobs of a shared context do not disturb it.
 */
final class JobMonitor extends SparkListener {
    private final String jobGroup;
    private final int[] tilesPerPartition;
    private final Progress progress;
    private final Set<Integer> stages = new HashSet<>();
    private final BitSet done = new BitSet();
    private final Set<String> executors = new HashSet<>();
    private int attempts;
    private int retries;
    private int failures;
    /** Whether Spark has started a job of the group: the executor watch is armed from then on. */
    private boolean jobStarted;

    /**
     * @param jobGroup          the job group of the render's jobs
     * @param tilesPerPartition tiles of each partition, by partition index
     * @param progress          the progress to advance, in tiles
     */
    JobMonitor(String jobGroup, int[] tilesPerPartition, Progress progress) {
        this.jobGroup = jobGroup;
        this.tilesPerPartition = tilesPerPartition.clone();
        this.progress = progress;
    }

    @Override
    public synchronized void onJobStart(SparkListenerJobStart jobStart) {
        if (jobStart.properties() == null || !jobGroup.equals(jobStart.properties().getProperty("spark.jobGroup.id")))
            return;
        for (Object stage : CollectionConverters.asJava(jobStart.stageIds())) stages.add((Integer) stage);
        jobStarted = true;
        notifyAll();
    }

    /**
     * Waits until Spark has started a job of the group (the listener hears of it just after the
     * submission).
     *
     * @throws InterruptedException when the waiting thread is interrupted (the job ended first)
     */
    synchronized void awaitJobStart() throws InterruptedException {
        while (!jobStarted) wait();
    }

    @Override
    public synchronized void onTaskEnd(SparkListenerTaskEnd taskEnd) {
        if (!stages.contains(taskEnd.stageId())) return;
        TaskInfo info = taskEnd.taskInfo();
        ++attempts;
        if (info.attemptNumber() > 0) ++retries;
        executors.add(info.executorId());
        if (taskEnd.reason() != Success$.MODULE$) {
            ++failures;
            return;
        }
        int partition = info.index();
        if (!done.get(partition)) { // a speculative copy that also succeeded counts once
            done.set(partition);
            progress.advance(tilesPerPartition[partition]);
            notifyAll();
        }
    }

    /**
     * Waits until the listener has seen every partition succeed: Spark delivers events after the
     * job's result, and a partition's failed attempts before its success, so the counts are then
     * complete.
     *
     * @param millis how long to wait at most
     * @throws InterruptedException when the waiting thread is interrupted
     */
    synchronized void awaitAll(long millis) throws InterruptedException {
        long end = System.nanoTime() + millis * 1_000_000;
        for (long left = millis; done.cardinality() < tilesPerPartition.length && left > 0;
                left = (end - System.nanoTime()) / 1_000_000)
            wait(left);
    }

    /** @return the job group whose jobs this monitor counts */
    String jobGroup() {
        return jobGroup;
    }

    /** @return task attempts ended, failed ones and retries included */
    synchronized int attempts() {
        return attempts;
    }

    /** @return attempts that were retries of a failed (or speculated) task */
    synchronized int retries() {
        return retries;
    }

    /** @return attempts that failed */
    synchronized int failures() {
        return failures;
    }

    /** @return distinct executors that ran an attempt */
    synchronized int executors() {
        return executors.size();
    }
}
