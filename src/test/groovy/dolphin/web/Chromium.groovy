package dolphin.web

import org.openqa.selenium.chrome.ChromeDriver
import org.openqa.selenium.chrome.ChromeDriverService
import org.openqa.selenium.chrome.ChromeOptions

/** Debian's chromium and chromium-driver (apt; .ci/run installs them), headless, for the browser tests. */
final class Chromium {
    static final File BROWSER = new File('/usr/bin/chromium')
    static final File DRIVER = new File('/usr/bin/chromedriver')

    static boolean available() {
        BROWSER.canExecute() && DRIVER.canExecute()
    }

    /** A headless browser; both paths given, so Selenium looks nothing up on the network. */
    static ChromeDriver start() {
        def options = new ChromeOptions()
        options.setBinary(BROWSER)
        options.addArguments('--headless=new', '--no-sandbox', '--disable-gpu', '--disable-dev-shm-usage',
                '--window-size=1440,900')
        def service = new ChromeDriverService.Builder().usingDriverExecutable(DRIVER).build()
        new ChromeDriver(service, options)
    }
}
