/** Every page of the book on a desk, 1280 px wide, each loaded once for all the checks of every-page.mjs. */
import { sweepEveryPage } from './every-page.mjs';

sweepEveryPage(1280);
